// Verification (label `verification`) of `ejecta converge` (coupling/convergence_study, issue
// 23): on problems with exact answers, the Richardson-extrapolated value lies within one GCI band
// of the exact value and nearer to it than the finest run: the 1D Sedov blast's shock radius at
// t = 0.02 s (exact 0.35, the Sedov-Taylor solution; sim/exact/sedov.hpp) and the Sod tube's L1
// errors (exact 0). Where Celik et al. (2008) put the band, about the finest value, it holds the
// exact value too. Where the levels are not in the asymptotic range (the Sod errors at factors 4
// to 1, whose changes grow) no extrapolation is claimed and the band must hold the exact value.
// Factors 4, 2, sqrt 2 and 1 of the problems' own spacings
// (100 to 400, 112 to 450 particles); and the Sedov blast at factors 2, 1.5, 1.25, 1, where the
// order (5.3) is out of range and the band reported (the least-squares band over the four levels,
// wider than the fallback) must hold the exact radius; and all four quantities at six levels,
// where each band is the least-squares one and must hold its exact value.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "coupling/convergence_study.hpp"

namespace ejecta::coupling {
namespace {

const verify::GridConvergence& convergenceOf(const ConvergenceResult& r, const std::string& q) {
  for (const QuantityConvergence& c : r.quantities)
    if (c.name == q) return c.convergence;
  throw std::invalid_argument("no quantity " + q);
}

void expectWithinItsUncertainty(const ConvergenceResult& r, const std::string& q, double exact) {
  const verify::GridConvergence& g = convergenceOf(r, q);
  ASSERT_TRUE(g.asymptotic) << q << ": " << g.note;
  const double finest = r.levels.back().values.at(q);
  std::printf("%s: finest %.6g +- %.3g, extrapolated %.6g (order %.2f), exact %.6g\n", q.c_str(), finest,
              g.uncertainty, g.extrapolated, g.order, exact);
  EXPECT_LE(std::abs(g.extrapolated - exact), g.uncertainty) << q;
  // And the extrapolation is nearer the exact value than the finest run.
  EXPECT_LT(std::abs(g.extrapolated - exact), std::abs(finest - exact)) << q;
  EXPECT_LE(std::abs(finest - exact), g.uncertainty) << q;
}

TEST(VerifyConverge, TheSedovShockRadiusExtrapolatesToTheExactRadius) {
  ConvergenceOptions o;
  o.factors = {4.0, 2.0, std::sqrt(2.0), 1.0};
  o.quantities = {"shock_radius", "shock_radius_exact"};
  const ConvergenceResult r = runVerificationConvergence("sedov_1d", o);
  ASSERT_EQ(r.levels.size(), 4u);
  EXPECT_GT(r.levels.front().spacing, r.levels.back().spacing);  // coarsest first
  expectWithinItsUncertainty(r, "shock_radius", r.levels.back().values.at("shock_radius_exact"));
  // Finer steps between the levels: the radius, the peak of a binned profile, moves by the bin,
  // and the three finest give an order of 5.3. Celik's band missed the exact radius; out of the
  // asymptotic range the fallback band (order 1, factor of safety 3) must hold it.
  o.factors = {2.0, 1.5, 1.25, 1.0};
  const ConvergenceResult steps = runVerificationConvergence("sedov_1d", o);
  const verify::GridConvergence& g = convergenceOf(steps, "shock_radius");
  EXPECT_GT(g.order, 2.0);
  EXPECT_FALSE(g.asymptotic);
  // The least-squares band over the four levels, wider than the three finest's fallback.
  EXPECT_EQ(g.basis, verify::UncertaintyBasis::LeastSquares);
  std::printf("shock_radius, factors 2 to 1: finest +- %.3g (%s); least squares: order %.3g, +- %.3g\n",
              g.uncertainty, verify::uncertaintyBasisName(g.basis), g.leastSquares.order, g.leastSquares.uncertainty);
  const ConvergenceLevel& finest = steps.levels.back();
  const double error = std::abs(finest.values.at("shock_radius") - finest.values.at("shock_radius_exact"));
  EXPECT_LE(error, g.uncertainty);
  // The three finest's fallback alone (order 1, factor of safety 3) holds it too.
  const ConvergenceLevel& next = steps.levels[steps.levels.size() - 2];
  const double fallback = 3.0 * std::abs(next.values.at("shock_radius") - finest.values.at("shock_radius")) /
                          (next.spacing / finest.spacing - 1.0);
  EXPECT_LE(error, fallback);
}

TEST(VerifyConverge, TheSodErrorsWhoseChangesGrowClaimNoOrderAndTheirBandsHoldZero) {
  // At factors 4, 2, sqrt 2 and 1 the three finest levels' L1 errors change more between the two
  // finest than between the next two (L1(rho): 0.00115 then 0.00179): the changes grow, so no
  // converging power of h fits them. Celik's |ln| read orders of 1.28, 1.02 and 2.35 from them
  // (and its band for L1(P), 0.00244, missed the finest error, 0.00431). Now no order and no
  // extrapolation are claimed, and each band (the fallback, order 1, factor of safety 3) must
  // hold the exact 0.
  ConvergenceOptions o;
  o.factors = {4.0, 2.0, std::sqrt(2.0), 1.0};
  o.quantities = {"L1_density", "L1_velocity", "L1_pressure"};
  const ConvergenceResult r = runVerificationConvergence("sod_1d", o);
  for (const char* q : {"L1_density", "L1_velocity", "L1_pressure"}) {
    const verify::GridConvergence& g = convergenceOf(r, q);
    const double finest = r.levels.back().values.at(q);
    std::printf("%s: finest %.6g +- %.3g (%s; %s)\n", q, finest, g.uncertainty, verify::uncertaintyBasisName(g.basis),
                g.note.c_str());
    EXPECT_FALSE(g.valid) << q;
    EXPECT_FALSE(g.asymptotic) << q;
    EXPECT_NE(g.note.find("monotone divergence"), std::string::npos) << q << ": " << g.note;
    EXPECT_EQ(g.basis, verify::UncertaintyBasis::FormalFallback) << q;  // wider than the fit's here
    EXPECT_LE(finest, g.uncertainty) << q;
  }
  EXPECT_THROW(runVerificationConvergence("sod_1d", {.factors = {2.0, 1.0}, .quantities = {"no_such"}}),
               std::invalid_argument);
}

TEST(VerifyConverge, TheLeastSquaresBandOverSixLevelsHoldsTheExactValues) {
  // Six levels (factors 4 to 0.7071, a ratio sqrt 2 apart: 100 to 566 particles): every quantity
  // gets Eca & Hoekstra's band from all six (wider than the three finest's), and each must hold
  // its exact value about the finest run, which is the band's claim. Measured 2026-12-07: the
  // radius 0.34737 +- 0.00652 (exact 0.35); L1(rho) 0.00318 +- 0.00709, L1(v) 0.00963 +- 0.0128,
  // L1(P) 0.00377 +- 0.0046 (exact 0; the last at the fit's order 0.96 and factor 1.25, whose
  // three finest give an order of 4.4, out of range).
  ConvergenceOptions o;
  o.factors = {4.0, 2.0 * std::sqrt(2.0), 2.0, std::sqrt(2.0), 1.0, std::sqrt(0.5)};
  o.quantities = {"shock_radius", "shock_radius_exact"};
  const ConvergenceResult sedov = runVerificationConvergence("sedov_1d", o);
  o.quantities = {"L1_density", "L1_velocity", "L1_pressure"};
  const ConvergenceResult sod = runVerificationConvergence("sod_1d", o);
  ASSERT_EQ(sod.levels.size(), 6u);
  auto expectHeld = [](const ConvergenceResult& r, const std::string& q, double exact) {
    const verify::GridConvergence& g = convergenceOf(r, q);
    const double finest = r.levels.back().values.at(q);
    std::printf("%s, six levels: finest %.6g +- %.3g (%s; least squares: order %.3g, F_s %.3g)\n", q.c_str(), finest,
                g.uncertainty, verify::uncertaintyBasisName(g.basis), g.leastSquares.order,
                g.leastSquares.safetyFactor);
    EXPECT_EQ(g.basis, verify::UncertaintyBasis::LeastSquares) << q;
    EXPECT_LE(std::abs(finest - exact), g.uncertainty) << q;
  };
  expectHeld(sedov, "shock_radius", sedov.levels.back().values.at("shock_radius_exact"));
  expectHeld(sod, "L1_density", 0.0);
  expectHeld(sod, "L1_velocity", 0.0);
  expectHeld(sod, "L1_pressure", 0.0);
  // Both the radius and L1(v) are in the asymptotic range there (orders 0.92 and 1.59 from the
  // three finest, which the fit agrees with): their extrapolations are within the band of the
  // exact value and nearer to it than the finest run.
  expectWithinItsUncertainty(sedov, "shock_radius", sedov.levels.back().values.at("shock_radius_exact"));
  expectWithinItsUncertainty(sod, "L1_velocity", 0.0);
}

}  // namespace
}  // namespace ejecta::coupling
