#pragma once
// What the verification tests of the fluid options (IAD gradients, generalised volume elements,
// Riemann-solver dissipation) share: a verification problem run with scene overrides, and the
// same problem run with an option and without it, the finest levels' blast measures printed side
// by side. The bounds stay in each test: each option promises something different.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "sim/verify/verification.hpp"

namespace ejecta::test {

// `problem` with `overrides` (--set lines) at the problem's levels (resolutions 0) or its first n.
inline verify::Report runVerification(const std::string& problem,
                                      std::vector<std::string> overrides, int resolutions = 0) {
  verify::Options options;
  options.resolutions = resolutions;
  options.overrides = std::move(overrides);
  return verify::runProblem(problem, options);
}

struct OptionAgainstStandard {
  verify::Report option, standard;  // the same runs with and without the option's setting
  const verify::ResolutionRun& finestOption() const { return option.runs.back(); }
  const verify::ResolutionRun& finestStandard() const { return standard.runs.back(); }
};

// A blast problem (sedov_1d, sedov_2d, ...) with `common` overrides, once more with `setting` too;
// prints the finest levels' L1(rho), shock radius error, peak density and centre pressure of the
// option, each with the standard run's in brackets (`standardName` says what that run is).
inline OptionAgainstStandard blastWithAndWithout(const std::string& problem,
                                                 const std::vector<std::string>& common,
                                                 const std::string& setting,
                                                 const char* standardName, int resolutions = 0) {
  std::vector<std::string> withOption = common;
  withOption.push_back(setting);
  OptionAgainstStandard runs{runVerification(problem, withOption, resolutions),
                             runVerification(problem, common, resolutions)};
  const verify::ResolutionRun &o = runs.finestOption(), &s = runs.finestStandard();
  std::printf("  %s %.3g m, %s: L1 %.4g (%s %.4g), shock %.3g (%.3g), peak %.3g (%.3g), centre "
              "%.3g (%.3g), dE/E %.3g\n",
              problem.c_str(), o.spacing, setting.c_str(), o.metric("L1_density"), standardName,
              s.metric("L1_density"), o.metric("shock_radius_error"),
              s.metric("shock_radius_error"), o.metric("peak_density_ratio"),
              s.metric("peak_density_ratio"), o.metric("centre_pressure_ratio"),
              s.metric("centre_pressure_ratio"), o.energyError);
  return runs;
}

// Converging: each level's `metric` below the coarser level's.
inline void expectEachLevelBelowTheLast(const verify::Report& report, const char* metric) {
  for (std::size_t n = 1; n < report.runs.size(); ++n)
    EXPECT_LT(report.runs[n].metric(metric), report.runs[n - 1].metric(metric))
        << report.problem << ": " << metric << " at level " << n;
}

// The 2D Sedov one level coarser than the problem's (0.01 m, 11,443 particles; the deposit's width
// with it): the options' 2D comparisons at a quarter of the cost.
inline const std::vector<std::string> kSedov2DAtOneCentimetre = {"bodies[0].spacing=0.01",
                                                                  "energy_deposits[0].width=0.02"};

}  // namespace ejecta::test
