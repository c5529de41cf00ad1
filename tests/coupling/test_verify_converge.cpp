// Verification (label `verification`) of `ejecta converge` (coupling/convergence_study, issue
// 23): on problems with exact answers, the Richardson-extrapolated value lies within one GCI band
// of the exact value and nearer to it than the finest run: the 1D Sedov blast's shock radius at
// t = 0.02 s (exact 0.35, the Sedov-Taylor solution; sim/exact/sedov.hpp) and the Sod tube's L1
// errors (exact 0). Where Celik et al. (2008) put the band, about the finest value, it holds the
// exact value too, except for the Sod L1(P): its observed order (2.35) is above a shock's first
// order and the band (2.4e-3) is narrower than the finest error (4.3e-3): the GCI can under-
// estimate, and docs/convergence.md says so. Factors 4, 2, sqrt 2 and 1 of the problems' own
// spacings (100 to 400, 112 to 450 particles).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupling/convergence_study.hpp"

namespace ejecta::coupling {
namespace {

enum class FinestBand { HoldsTheExactValue, MissesIt };

void expectWithinItsUncertainty(const ConvergenceResult& r, const std::string& q, double exact,
                                FinestBand finestBand = FinestBand::HoldsTheExactValue) {
  for (const QuantityConvergence& c : r.quantities) {
    if (c.name != q) continue;
    const verify::GridConvergence& g = c.convergence;
    ASSERT_TRUE(g.valid) << q << ": " << g.note;
    const double finest = r.levels.back().values.at(q);
    std::printf("%s: finest %.6g +- %.3g, extrapolated %.6g (order %.2f), exact %.6g\n", q.c_str(), finest,
                g.uncertainty, g.extrapolated, g.order, exact);
    EXPECT_LE(std::abs(g.extrapolated - exact), g.uncertainty) << q;
    // And the extrapolation is nearer the exact value than the finest run.
    EXPECT_LT(std::abs(g.extrapolated - exact), std::abs(finest - exact)) << q;
    if (finestBand == FinestBand::HoldsTheExactValue)
      EXPECT_LE(std::abs(finest - exact), g.uncertainty) << q;
    else
      EXPECT_GT(std::abs(finest - exact), g.uncertainty) << q << ": the band now holds it; say so in docs/convergence.md";
    return;
  }
  FAIL() << "no quantity " << q;
}

TEST(VerifyConverge, TheSedovShockRadiusExtrapolatesToTheExactRadius) {
  ConvergenceOptions o;
  o.factors = {4.0, 2.0, std::sqrt(2.0), 1.0};
  o.quantities = {"shock_radius", "shock_radius_exact"};
  const ConvergenceResult r = runVerificationConvergence("sedov_1d", o);
  ASSERT_EQ(r.levels.size(), 4u);
  EXPECT_GT(r.levels.front().spacing, r.levels.back().spacing);  // coarsest first
  expectWithinItsUncertainty(r, "shock_radius", r.levels.back().values.at("shock_radius_exact"));
}

TEST(VerifyConverge, TheSodErrorsExtrapolateToZero) {
  ConvergenceOptions o;
  o.factors = {4.0, 2.0, std::sqrt(2.0), 1.0};
  o.quantities = {"L1_density", "L1_velocity", "L1_pressure"};
  const ConvergenceResult r = runVerificationConvergence("sod_1d", o);
  expectWithinItsUncertainty(r, "L1_density", 0.0);
  expectWithinItsUncertainty(r, "L1_velocity", 0.0);
  expectWithinItsUncertainty(r, "L1_pressure", 0.0, FinestBand::MissesIt);
  EXPECT_THROW(runVerificationConvergence("sod_1d", {.factors = {2.0, 1.0}, .quantities = {"no_such"}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::coupling
