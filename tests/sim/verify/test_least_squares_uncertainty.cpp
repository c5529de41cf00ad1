// The least-squares uncertainty over four or more levels (sim/verify/least_squares_uncertainty,
// Eca & Hoekstra 2014; issue 23): exact powers of h recovered, each branch of the procedure worked
// by hand, and the case it exists for, a real study whose two finest levels agree by chance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "sim/verify/grid_convergence.hpp"
#include "sim/verify/least_squares_uncertainty.hpp"

namespace ejecta::verify {
namespace {

TEST(LeastSquaresUncertainty, RecoversAnExactPowerOfTheSpacing) {
  // phi = 5 - 0.4 h^0.8 at five spacings, in no order: the fit is exact (sigma at round-off), so
  // p = 0.8 and phi_0 = 5 to the search's tolerance, eps = 0.4 (0.1)^0.8 and, p in [0.5, 1.05),
  // U = 1.25 eps, which holds the exact limit 5 by the margin 0.25 eps.
  const std::vector<double> h = {0.2, 0.1, 0.4, 0.14, 0.28};
  std::vector<double> phi;
  for (double x : h) phi.push_back(5.0 - 0.4 * std::pow(x, 0.8));
  const LeastSquaresUncertainty u = leastSquaresUncertainty(h, phi, 1.0);
  ASSERT_TRUE(u.available) << u.note;
  EXPECT_NEAR(u.order, 0.8, 1e-6);
  EXPECT_FALSE(u.orderAtSearchBound);
  EXPECT_NEAR(u.extrapolated, 5.0, 1e-8);
  const double eps = 0.4 * std::pow(0.1, 0.8);
  EXPECT_NEAR(u.errorEstimate, eps, 1e-8);
  EXPECT_LT(u.standardDeviation, 1e-8);
  EXPECT_TRUE(u.goodFit);
  EXPECT_DOUBLE_EQ(u.safetyFactor, 1.25);
  EXPECT_NEAR(u.uncertainty, 1.25 * eps, 1e-7);
  EXPECT_DOUBLE_EQ(u.estimateOrder, u.order);
  EXPECT_NE(u.note.find("from phi0 + a h^p"), std::string::npos) << u.note;
}

TEST(LeastSquaresUncertainty, AnOrderAboveTheFormalIsEstimatedWithoutIt) {
  // phi = 2 + h^2 at formal order 1: the fit finds p = 2, above the formal order, so the error is
  // estimated from the better of phi_0 + a h and phi_0 + a h + b h^2. The second is exact here
  // (a = 0, b = 1): phi_0 = 2, eps = h_1^2 = 0.01, sigma = 0, and with a factor of safety 3
  // (p is not below 1.05 p_formal) U = 0.03.
  const std::vector<double> h = {0.1, 0.15, 0.2, 0.3};
  std::vector<double> phi;
  for (double x : h) phi.push_back(2.0 + x * x);
  const LeastSquaresUncertainty u = leastSquaresUncertainty(h, phi, 1.0);
  ASSERT_TRUE(u.available) << u.note;
  EXPECT_NEAR(u.order, 2.0, 1e-6);
  EXPECT_NE(u.note.find("above the formal order"), std::string::npos) << u.note;
  EXPECT_NE(u.note.find("a h + b h^2"), std::string::npos) << u.note;
  EXPECT_DOUBLE_EQ(u.estimateOrder, 1.0);
  EXPECT_NEAR(u.extrapolated, 2.0, 1e-10);
  EXPECT_DOUBLE_EQ(u.safetyFactor, 3.0);
  EXPECT_NEAR(u.uncertainty, 0.03, 1e-9);
  // At formal order 2 the same data are in range: the power fit itself and factor 1.25.
  const LeastSquaresUncertainty second = leastSquaresUncertainty(h, phi, 2.0);
  EXPECT_DOUBLE_EQ(second.safetyFactor, 1.25);
  EXPECT_NEAR(second.uncertainty, 1.25 * 0.01, 1e-7);
  // phi = 2 + h^3: neither candidate is exact; the two-term form fits better (sigma 2.9e-4) and
  // its band, 0.0143, holds the finest level's error of 0.001.
  std::vector<double> cubic;
  for (double x : h) cubic.push_back(2.0 + x * x * x);
  const LeastSquaresUncertainty third = leastSquaresUncertainty(h, cubic, 1.0);
  ASSERT_TRUE(third.available) << third.note;
  EXPECT_NEAR(third.order, 3.0, 1e-6);
  EXPECT_NE(third.note.find("a h + b h^2"), std::string::npos) << third.note;
  EXPECT_LE(std::abs(cubic[0] - 2.0), third.uncertainty);
}

TEST(LeastSquaresUncertainty, AnOrderBelowHalfTakesTheBestFixedOrderFit) {
  // phi = 1 + h^0.3: too slow for the error estimate from the power fit; the best of the paper's
  // fixed-order fits (h, h^2, h + h^2) gives it, at a factor of safety 3. Those fits assume a
  // faster convergence than the data show, so alone they understate here (0.31 against an error
  // of 0.50); gridConvergence keeps the wider band, and the three finest's fallback, at their
  // lower observed order 0.3, holds the limit.
  const std::vector<double> h = {0.1, 0.2, 0.4, 0.8, 1.6};
  std::vector<double> phi;
  for (double x : h) phi.push_back(1.0 + std::pow(x, 0.3));
  const LeastSquaresUncertainty u = leastSquaresUncertainty(h, phi, 1.0);
  ASSERT_TRUE(u.available) << u.note;
  EXPECT_NEAR(u.order, 0.3, 1e-6);
  EXPECT_NE(u.note.find("below 0.5"), std::string::npos) << u.note;
  EXPECT_DOUBLE_EQ(u.safetyFactor, 3.0);
  EXPECT_LT(u.uncertainty, std::abs(phi[0] - 1.0)) << "the fixed-order fits now hold it: update the comment";
  const GridConvergence g = gridConvergence(h, phi);
  EXPECT_EQ(g.basis, UncertaintyBasis::FormalFallback);
  EXPECT_NEAR(g.bandOrder, 0.3, 1e-9);
  EXPECT_LE(std::abs(phi[0] - 1.0), g.uncertainty);
}

TEST(LeastSquaresUncertainty, ScatterAsLargeAsTheDataRangeWidensTheBand) {
  // Values that alternate with no trend: no power of h fits them (sigma >= Delta_M = 1/4), and the
  // band, 3 (sigma / Delta_M)(eps + sigma + |phi_1 - fit_1|), spans every level's value.
  const std::vector<double> h = {1.0, 2.0, 3.0, 4.0, 5.0};
  const std::vector<double> phi = {1.0, 2.0, 1.0, 2.0, 1.0};
  const LeastSquaresUncertainty u = leastSquaresUncertainty(h, phi, 1.0);
  ASSERT_TRUE(u.available) << u.note;
  EXPECT_DOUBLE_EQ(u.dataRange, 0.25);
  EXPECT_FALSE(u.goodFit);
  EXPECT_DOUBLE_EQ(u.safetyFactor, 3.0);
  EXPECT_GE(u.uncertainty, 1.0);
}

TEST(LeastSquaresUncertainty, TheFollowerFluxStudySeesTheScatterOfItsLevels) {
  // The headline study follower_flux_1ms (bench/headline.toml, run 2026-12-07): side0's peak
  // flux, W/m^2, at 0.5 to 0.0884 m. Its two finest agree to 0.08%, so the three finest's band
  // (Roache's fallback) is +-0.6% and does not hold even the third finest level, 4% below. The
  // fit over all six sees the scatter: its band (8.5%, factor of safety 3) is over ten times
  // wider and holds the three finest. (The offline study's 0.0625 m level, 1.12e6, lies 10.6%
  // below: outside this band too, docs/convergence.md.)
  const std::vector<double> h = {0.5, 0.35355, 0.25, 0.17678, 0.125, 0.088388};
  const std::vector<double> flux = {1609533.68, 1374277.38, 1378255.65, 1201122.26, 1251864.40, 1252858.66};
  const GridConvergence threeOnly = gridConvergence({h[3], h[4], h[5]}, {flux[3], flux[4], flux[5]});
  EXPECT_LT(threeOnly.uncertainty, flux[5] - flux[3]);
  const GridConvergence all = gridConvergence(h, flux);
  ASSERT_TRUE(all.leastSquares.available) << all.leastSquares.note;
  EXPECT_EQ(all.basis, UncertaintyBasis::LeastSquares);
  EXPECT_NE(all.note.find("the band from all levels"), std::string::npos) << all.note;
  EXPECT_DOUBLE_EQ(all.bandOrder, all.leastSquares.estimateOrder);
  EXPECT_GT(all.uncertainty, 10.0 * threeOnly.uncertainty);
  EXPECT_LE(flux[5] - flux[3], all.uncertainty);
  // Not so wide as to say nothing: within the spread of the levels.
  EXPECT_LT(all.uncertainty, flux[0] - flux[3]);
  // The study's seventh level, 0.0625 m (2026-12-07): 1.11503e6, 11% below. The three finest now
  // alternate, and Roache's fallback on that last swing, 3 x 1.378e5 / (sqrt 2 - 1), would be
  // +-1.0e6 (90%). The fit over the seven levels is the band there instead (factor of safety 3):
  // it holds every level from 0.177 m down and is a third of the fallback.
  std::vector<double> h7 = h, flux7 = flux;
  h7.push_back(0.0625);
  flux7.push_back(1115032.11);
  const GridConvergence seven = gridConvergence(h7, flux7);
  EXPECT_TRUE(seven.oscillatory);
  EXPECT_EQ(seven.basis, UncertaintyBasis::LeastSquares);
  EXPECT_DOUBLE_EQ(seven.uncertainty, seven.leastSquares.uncertainty);
  for (std::size_t i = 3; i < flux7.size(); ++i) EXPECT_LE(std::abs(flux7[i] - flux7[6]), seven.uncertainty) << i;
  const double fallback = 3.0 * (flux7[5] - flux7[6]) / (h7[5] / h7[6] - 1.0);
  EXPECT_LT(seven.uncertainty, fallback / 3.0);
}

TEST(LeastSquaresUncertainty, AnOscillationWiderThanTheFitKeepsHalfItsSpread) {
  // Five levels near 1 + 0.1 h whose finest three alternate (1.127, 1.118, 1.189): the fit over
  // all five gives +-0.0284, less than half the three finest's spread, 0.0355, which is the band
  // (Stern et al. 2001's half amplitude), and the labels say so rather than quote the fit's
  // factor of safety.
  const std::vector<double> h = {1.0, 1.4142, 2.0, 2.8284, 4.0};
  const GridConvergence g = gridConvergence(h, {1.127, 1.118, 1.189, 1.251, 1.437});
  ASSERT_TRUE(g.leastSquares.available) << g.leastSquares.note;
  EXPECT_TRUE(g.oscillatory);
  EXPECT_EQ(g.basis, UncertaintyBasis::LeastSquares);
  EXPECT_LT(g.leastSquares.uncertainty, 0.0355);
  EXPECT_NEAR(g.uncertainty, 0.0355, 1e-12);
  EXPECT_TRUE(g.bandAtHalfSpread);
  EXPECT_NE(g.note.find("raised to half the three finest's spread"), std::string::npos) << g.note;
  EXPECT_EQ(describeBand(g, h.size()),
            "half the three finest's spread, wider than the least-squares band over 5 levels (factor of safety 3)");
}

TEST(LeastSquaresUncertainty, GridConvergenceKeepsTheWiderBandAndChecksTheRange) {
  // phi = 1 - 3 h^1.3 and a coarsest value far off it: the three finest alone are in the
  // asymptotic range (p = 1.3, Celik's band), but the four together have no order (the fit runs
  // to the search's bound), so no extrapolation is claimed and the band is the wider.
  auto phi = [](double h) { return 1.0 - 3.0 * std::pow(h, 1.3); };
  const std::vector<double> h = {0.1, 0.14, 0.2, 0.3};
  const GridConvergence threeFinest = gridConvergence({h[0], h[1], h[2]}, {phi(h[0]), phi(h[1]), phi(h[2])});
  ASSERT_TRUE(threeFinest.asymptotic) << threeFinest.note;
  const GridConvergence g = gridConvergence(h, {phi(h[0]), phi(h[1]), phi(h[2]), 42.0});
  EXPECT_NEAR(g.order, 1.3, 1e-9);
  EXPECT_TRUE(g.leastSquares.orderAtSearchBound);  // the best p is the search's 10: no order
  EXPECT_FALSE(g.asymptotic);
  EXPECT_NE(g.note.find("do not follow one power"), std::string::npos) << g.note;
  EXPECT_EQ(g.basis, UncertaintyBasis::LeastSquares);
  EXPECT_GT(g.uncertainty, threeFinest.uncertainty);
  // On the exact sequence at formal order 2 the fit is exact and its order in range, and the
  // procedure reduces to Celik's GCI (Eca & Hoekstra's design): 1.25 eps on both sides.
  const std::vector<double> exact = {phi(h[0]), phi(h[1]), phi(h[2]), phi(h[3])};
  const GridConvergence smooth = gridConvergence(h, exact, 2.0);
  EXPECT_TRUE(smooth.asymptotic) << smooth.note;
  EXPECT_NEAR(smooth.leastSquares.order, 1.3, 1e-6);
  EXPECT_NEAR(smooth.leastSquares.uncertainty, 1.25 * 3.0 * std::pow(0.1, 1.3), 1e-8);
  EXPECT_NEAR(smooth.uncertainty, smooth.leastSquares.uncertainty, 1e-8);
  // At the default formal order 1 the fit's order, 1.3, is above it: the estimate at order 1 and
  // a factor of safety 3 make the band wider than Celik's, which is the one reported; the three
  // finest and the fit still agree the range is asymptotic.
  const GridConvergence first = gridConvergence(h, exact);
  EXPECT_TRUE(first.asymptotic) << first.note;
  EXPECT_EQ(first.basis, UncertaintyBasis::LeastSquares);
  EXPECT_DOUBLE_EQ(first.leastSquares.safetyFactor, 3.0);
  EXPECT_GT(first.uncertainty, 1.25 * 3.0 * std::pow(0.1, 1.3));
  EXPECT_FALSE(first.bandAtHalfSpread);
  EXPECT_EQ(describeBand(first, h.size()), "least-squares band over 4 levels (factor of safety 3)");
  EXPECT_STREQ(uncertaintyBasisName(UncertaintyBasis::LeastSquares), "least squares");
  // Two equal finest values give three levels no order and no band; with a fourth the fit over
  // all of them gives one.
  const GridConvergence equal = gridConvergence({1.0, 2.0, 4.0, 8.0}, {1.0, 1.0, 1.2, 1.1});
  EXPECT_FALSE(equal.valid);
  EXPECT_NE(equal.note.find("two finest values are equal"), std::string::npos) << equal.note;
  EXPECT_EQ(equal.basis, UncertaintyBasis::LeastSquares);
  EXPECT_GT(equal.uncertainty, 0.0);
  EXPECT_DOUBLE_EQ(equal.uncertainty, equal.leastSquares.uncertainty);
}

TEST(LeastSquaresUncertainty, SaysWhyNotAndRefusesBadInput) {
  EXPECT_FALSE(leastSquaresUncertainty({0.1, 0.2, 0.4}, {1.0, 2.0, 3.0}, 1.0).available);
  EXPECT_FALSE(leastSquaresUncertainty({0.1, 0.2, 0.4, 0.8}, {3.0, 3.0, 3.0, 3.0}, 1.0).available);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const LeastSquaresUncertainty bad = leastSquaresUncertainty({0.1, 0.2, 0.4, 0.8}, {1.0, nan, 2.0, 3.0}, 1.0);
  EXPECT_FALSE(bad.available);
  EXPECT_NE(bad.note.find("not finite"), std::string::npos);
  EXPECT_THROW(leastSquaresUncertainty({0.1, 0.2}, {1.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(leastSquaresUncertainty({0.1, 0.2, 0.3, 0.4}, {1, 2, 3, 4}, 0.0), std::invalid_argument);
  EXPECT_THROW(leastSquaresUncertainty({0.1, -0.2, 0.3, 0.4}, {1, 2, 3, 4}, 1.0), std::invalid_argument);
  EXPECT_THROW(leastSquaresUncertainty({0.1, nan, 0.3, 0.4}, {1, 2, 3, 4}, 1.0), std::invalid_argument);
  EXPECT_THROW(leastSquaresUncertainty({0.1, 0.2, 0.2, 0.4}, {1, 2, 3, 4}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::verify
