// Verification (label `verification`) of `ejecta converge` (coupling/convergence_study, issue
// 23): on problems with exact answers, the Richardson-extrapolated value lies within its own
// GCI uncertainty of the exact value: the 1D Sedov blast's shock radius at t = 0.02 s (exact
// 0.35, the Sedov-Taylor solution; sim/exact/sedov.hpp) and the Sod tube's L1 errors (exact 0).
// Factors 4, 2, sqrt 2 and 1 of the problems' own spacings (100 to 400, 112 to 450 particles).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coupling/convergence_study.hpp"

namespace ejecta::coupling {
namespace {

void expectWithinItsUncertainty(const ConvergenceResult& r, const std::string& q, double exact) {
  for (const QuantityConvergence& c : r.quantities) {
    if (c.name != q) continue;
    const verify::GridConvergence& g = c.convergence;
    ASSERT_TRUE(g.valid) << q << ": " << g.note;
    std::printf("%s: finest %.6g, extrapolated %.6g +- %.3g (order %.2f), exact %.6g\n", q.c_str(),
                r.levels.back().values.at(q), g.extrapolated, g.uncertainty, g.order, exact);
    EXPECT_LE(std::abs(g.extrapolated - exact), g.uncertainty) << q;
    // And the extrapolation is nearer the exact value than the finest run.
    EXPECT_LT(std::abs(g.extrapolated - exact), std::abs(r.levels.back().values.at(q) - exact)) << q;
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
  for (const std::string& q : o.quantities) expectWithinItsUncertainty(r, q, 0.0);
  EXPECT_THROW(runVerificationConvergence("sod_1d", {.factors = {2.0, 1.0}, .quantities = {"no_such"}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::coupling
