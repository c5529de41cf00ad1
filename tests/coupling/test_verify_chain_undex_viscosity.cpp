// The reconstructed viscosity on the problem it was built for, and on one it must not spoil:
// - the near field of scenes/undex_rz.toml (the 1 kg TNT sphere in a 0.4 m box to 0.18 ms, 5 mm)
//   against the converged 1D reference of the same model (`ejecta undex-reference`), through the
//   command line as a user runs them: the plain viscosity's weak-shock deficit must shrink, and
//   the crest must not ring;
// - Sedov's blast (`sedov_2d` at 0.01 m): the density error must not grow.
// docs/undex.md, "The reconstructed viscosity", has the full-size study.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "sim/sources/gauge_decay.hpp"
#include "sim/verify/verification.hpp"
#include "support/command_line.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

using test::kEjecta;
using test::runCommand;

// The near-field box of docs/undex.md ("Where the peak is lost") at 5 mm, gauges at 0.1-0.3 m.
const std::string kNearField =
    " --set 'bodies[0].spacing=\"5 mm\"' --set 'bodies[1].spacing=\"5 mm\"'"
    " --set 'domain.x.max=0.4' --set 'domain.y={min=0.0,max=0.4,lower=\"wall\",upper=\"open\"}'"
    " --set 'bodies[1].max=[0.4,0.4]' --set 'time.t_end=\"0.18 ms\"'"
    " --set 'gauges[0].position=[\"0.1 m\",0.0]' --set 'gauges[0].name=\"g010\"'"
    " --set 'gauges[1].position=[\"0.15 m\",0.0]' --set 'gauges[1].name=\"g015\"'"
    " --set 'gauges[2].position=[\"0.25 m\",0.0]' --set 'gauges[2].name=\"g025\"'"
    " --set 'gauges[3].position=[\"0.3 m\",0.0]' --set 'gauges[3].name=\"g030\"'";

struct Pulse {
  double peak = 0.0;     // overpressure [Pa]
  double rebound = 0.0;  // rise from the first trough behind the peak to the next crest, / peak
};

// Peak and ringing of every gauge in a gauges.csv / gauges_reference.csv.
std::map<std::string, Pulse> readPulses(const fs::path& csv) {
  const GaugePressures g = readGaugePressures(csv.string());
  std::map<std::string, Pulse> out;
  for (std::size_t k = 0; k < g.names.size(); ++k) {
    const ShockPulse pulse = measureShockPulse(g.time, g.pressure[k], 101325.0);
    std::vector<double> p = g.pressure[k];
    for (double& x : p) x = std::isfinite(x) ? x - 101325.0 : 0.0;
    std::size_t i = static_cast<std::size_t>(std::max_element(p.begin(), p.end()) - p.begin());
    while (i + 1 < p.size() && p[i + 1] <= p[i]) ++i;  // the first trough
    const double trough = p[i];
    while (i + 1 < p.size() && p[i + 1] >= p[i]) ++i;  // the crest after it
    out[g.names[k]] = {pulse.peakPressure, (p[i] - trough) / pulse.peakPressure};
  }
  return out;
}

TEST(UndexViscosity, ReconstructionClosesTheWeakShockDeficitWithoutRinging) {
  const fs::path dir =
      fs::temp_directory_path() / ("ejecta_verify_undex_viscosity_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string scene = std::string(EJECTA_SOURCE_DIR) + "/scenes/undex_rz.toml";
  // 2000 zones of 0.2 mm: the peaks are within 1% of 4000 zones' (measured -0.9% at 0.1 m, 0.1%
  // at 0.25 and 0.3 m), far inside the margins below; 3 s.
  std::string output;
  ASSERT_EQ(runCommand(kEjecta + " undex-reference " + scene + " --zones 2000 --out " +
                           (dir / "reference").string() + kNearField,
                       output),
            0)
      << output;
  for (const char* mode : {"none", "monotone"})
    ASSERT_EQ(runCommand(kEjecta + " run " + scene + " -j 1 --no-charts --out " +
                             (dir / mode).string() + kNearField +
                             " --set 'sph.viscosity.reconstruction=\"" + mode + "\"'",
                         output),
              0)
        << output;
  const auto reference = readPulses(dir / "reference" / "gauges_reference.csv");
  const auto plain = readPulses(dir / "none" / "gauges.csv");
  const auto monotone = readPulses(dir / "monotone" / "gauges.csv");
  for (const char* g : {"g010", "g015", "g025", "g030"})
    std::printf("%s: reference %.1f MPa, alpha = 1 %.1f MPa (%.3f), monotone %.1f MPa (%.3f), "
                "rebound %.3f / %.3f\n",
                g, reference.at(g).peak / 1e6, plain.at(g).peak / 1e6,
                plain.at(g).peak / reference.at(g).peak, monotone.at(g).peak / 1e6,
                monotone.at(g).peak / reference.at(g).peak, plain.at(g).rebound,
                monotone.at(g).rebound);
  // Where the shock has weakened (0.25, 0.3 m), the plain viscosity's front is wide against the
  // pulse and reads 19% low (measured 0.814, 0.817); the reconstruction reads 0.921, 0.939.
  // Asserted: within 10% of the reference, and at most half the plain run's deficit.
  for (const char* g : {"g025", "g030"}) {
    const double ratio = monotone.at(g).peak / reference.at(g).peak;
    const double plainRatio = plain.at(g).peak / reference.at(g).peak;
    EXPECT_GT(ratio, 0.90) << g;
    EXPECT_LT(ratio, 1.02) << g;  // a crest above the converged model would be overshoot
    EXPECT_LT(1.0 - ratio, 0.5 * (1.0 - plainRatio)) << g;
  }
  // Ringing: the crest is followed by a dip and a smaller second crest (measured rebounds
  // 0.05-0.07 of the peak at 0.1-0.3 m; the pair-limited "van_leer" gives 0.29 and is not
  // adopted for this reason; docs/undex.md). Asserted below 0.15 at every gauge.
  for (const char* g : {"g010", "g015", "g025", "g030"})
    EXPECT_LT(monotone.at(g).rebound, 0.15) << g;
  fs::remove_all(dir);
}

TEST(UndexViscosity, SedovDensityErrorDoesNotGrow) {
  // The reconstruction leaves less viscosity behind a strong blast, where SPH's post-shock noise
  // lives; the quadratic term keeps the raw approach for that reason. sedov_2d at 0.01 m (11,443
  // particles, 10-13 s): L1(rho) 0.3358 plain, 0.3446 monotone (+2.6%), 0.3570 van_leer (+6.3%),
  // measured. Asserted: monotone within 5% of plain. (sedov_rz at its 0.05 m: 0.2364 plain,
  // 0.2418 with this quadratic term, 0.2648 when the reconstruction also took it.)
  auto l1 = [](const std::string& mode) {
    verify::Options options;
    options.threads = 1;
    options.resolutions = 1;
    options.overrides = {"bodies[0].spacing=0.01",
                         "sph.viscosity.reconstruction=\"" + mode + "\""};
    const verify::Report r = verify::runProblem("sedov_2d", options);
    return r.runs.front().metric("L1_density");
  };
  const double plain = l1("none"), monotone = l1("monotone");
  std::printf("sedov_2d at 0.01 m: L1(rho) %.4f plain, %.4f monotone\n", plain, monotone);
  EXPECT_LT(monotone, 1.05 * plain);
}

}  // namespace
}  // namespace ejecta
