// Tests of the radial Euler reference solver (sim/exact/radial_euler.hpp): the planar case
// against the exact Riemann solution, conservation in cylindrical and spherical geometry,
// grid convergence and the physics of the 2D circular Sod problem (sod_2d); its speed is
// measured by bench/exact_solutions.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "sim/exact/radial_euler.hpp"
#include "sim/exact/riemann.hpp"

namespace {

using ejecta::exact::GasState;
using ejecta::exact::RadialRiemannSolution;
using ejecta::exact::RiemannProblem;

constexpr double kGamma = 1.4;
constexpr GasState kSodHigh{1.0, 0.0, 1.0};
constexpr GasState kSodLow{0.125, 0.0, 0.1};

// The sod_2d setup: high-pressure disc of radius 0.4 in ambient gas, run to t = 0.25.
constexpr double kDiscRadius = 0.4;
constexpr double kDomain = 1.0;
constexpr double kEndTime = 0.25;

RadialRiemannSolution solveCircularSod(int cells) {
  RadialRiemannSolution solution(2, kSodHigh, kSodLow, kDiscRadius, kGamma, kDomain, cells);
  solution.advanceTo(kEndTime);
  return solution;
}

// Midpoint-rule integral of |f - g| over [0, length] with many more samples than cells, so the
// sampling itself adds nothing visible to the distance between two piecewise-linear profiles.
double l1Distance(const std::function<double(double)>& f, const std::function<double(double)>& g,
                  double length) {
  constexpr int samples = 40000;
  const double h = length / samples;
  double sum = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double r = (k + 0.5) * h;
    sum += std::abs(f(r) - g(r));
  }
  return sum * h;
}

// Planar Sod tube, interface at x = 0.5 of [0, 1], at t = 0.2: the waves stay inside the domain
// (rarefaction head at 0.26, shock at 0.85), so the wall and the outflow boundary play no part.
double planarSodDensityError(int cells) {
  constexpr double interface = 0.5, t = 0.2;
  RadialRiemannSolution solution(1, kSodHigh, kSodLow, interface, kGamma, 1.0, cells);
  solution.advanceTo(t);
  const RiemannProblem exact(kSodHigh, kSodLow, kGamma);
  return l1Distance([&](double x) { return solution.at(x).rho; },
                    [&](double x) { return exact.sample((x - interface) / t).rho; }, 1.0);
}

TEST(ExactRadialEuler, PlanarCaseMatchesExactRiemannSolution) {
  const double error500 = planarSodDensityError(500);
  const double error1000 = planarSodDensityError(1000);
  const double error2000 = planarSodDensityError(2000);
  // Measured 3.7e-4 at 2000 cells (about 0.6 cells' worth of smearing per discontinuity);
  // 1e-3 leaves a factor ~3 for compiler and platform differences.
  EXPECT_LT(error2000, 1e-3);
  // With a shock and a contact, L1 converges at order between 2/3 (contact) and 1 (shock) for a
  // second-order scheme; measured ratios 1.8 per halving (order 0.85). 1.6 is order 0.68.
  EXPECT_GT(error500 / error1000, 1.6);
  EXPECT_GT(error1000 / error2000, 1.6);
}

TEST(ExactRadialEuler, PlanarStarStateMatchesExactValues) {
  constexpr double interface = 0.5, t = 0.2;
  RadialRiemannSolution solution(1, kSodHigh, kSodLow, interface, kGamma, 1.0, 2000);
  solution.advanceTo(t);
  const RiemannProblem exact(kSodHigh, kSodLow, kGamma);
  // Midway between contact and shock, well away from both: the flat star state.
  const double xi = 0.5 * (exact.starVelocity() + exact.rightHeadSpeed());
  const GasState star = solution.at(interface + xi * t);
  // Away from discontinuities the scheme is second order; measured deviations are 2e-6
  // relative. 1e-4 leaves margin yet fails for any error in the jump conditions or fluxes.
  EXPECT_NEAR(star.p, exact.starPressure(), 1e-4 * exact.starPressure());
  EXPECT_NEAR(star.u, exact.starVelocity(), 1e-4 * exact.starVelocity());
  EXPECT_NEAR(star.rho, exact.starDensityRight(), 1e-4 * exact.starDensityRight());
}

TEST(ExactRadialEuler, MassAndEnergyAreConservedInEveryGeometry) {
  for (int j = 1; j <= 3; ++j) {
    SCOPED_TRACE(j);
    RadialRiemannSolution solution(j, kSodHigh, kSodLow, kDiscRadius, kGamma, kDomain, 1000);
    const double mass0 = solution.totalMass();
    const double energy0 = solution.totalEnergy();
    solution.advanceTo(kEndTime);  // the outer shock is still inside rMax (at r < 0.84)
    ASSERT_EQ(solution.at(kDomain).p, kSodLow.p);
    // Fluxes telescope, so only round-off accumulates: ~1e-16 per cell and step over ~1000
    // cells and ~1200 steps; measured <= 4e-14 (j = 1), 7e-15 (j = 2), 1.5e-15 (j = 3).
    EXPECT_NEAR(solution.totalMass() / mass0, 1.0, 1e-12);
    EXPECT_NEAR(solution.totalEnergy() / energy0, 1.0, 1e-12);
  }
}

TEST(ExactRadialEuler, InitialTotalsUseTheGeometricMeasure) {
  // Uniform gas: mass = rho * (measure of the ball of radius rMax).
  constexpr double pi = 3.14159265358979323846;
  const GasState gas{2.0, 0.0, 3.0};
  const double expected[] = {2.0 * 1.5, 2.0 * pi * 1.5 * 1.5,
                             2.0 * 4.0 / 3.0 * pi * 1.5 * 1.5 * 1.5};
  for (int j = 1; j <= 3; ++j) {
    SCOPED_TRACE(j);
    const RadialRiemannSolution solution(j, gas, gas, 0.5, kGamma, 1.5, 300);
    const double expectedEnergy = expected[j - 1] / gas.rho * gas.p / (kGamma - 1.0);
    // Sums of 300 cell volumes that telescope to rMax^j: round-off only.
    EXPECT_NEAR(solution.totalMass(), expected[j - 1], 1e-13 * expected[j - 1]);
    EXPECT_NEAR(solution.totalEnergy(), expectedEnergy, 1e-13 * expectedEnergy);
  }
}

TEST(ExactRadialEuler, GasAtRestStaysExactlyAtRest) {
  // The momentum source p dA balances the pressure flux difference bit for bit.
  const GasState gas{0.7, 0.0, 2.5};
  for (int j = 1; j <= 3; ++j) {
    SCOPED_TRACE(j);
    RadialRiemannSolution solution(j, gas, gas, 0.3, kGamma, 1.0, 200);
    solution.advanceTo(0.5);
    for (double r : {0.0, 0.001, 0.2, 0.5, 0.999, 1.0}) {
      const GasState s = solution.at(r);
      EXPECT_EQ(s.u, 0.0) << "r = " << r;
      EXPECT_DOUBLE_EQ(s.rho, gas.rho) << "r = " << r;
      EXPECT_DOUBLE_EQ(s.p, gas.p) << "r = " << r;
    }
  }
}

TEST(ExactRadialEuler, CircularSodConvergesUnderRefinement) {
  const RadialRiemannSolution coarse = solveCircularSod(1000);
  const RadialRiemannSolution medium = solveCircularSod(2000);
  const RadialRiemannSolution fine = solveCircularSod(4000);
  auto density = [](const RadialRiemannSolution& s) {
    return [&s](double r) { return s.at(r).rho; };
  };
  const double coarseToMedium = l1Distance(density(coarse), density(medium), kDomain);
  const double mediumToFine = l1Distance(density(medium), density(fine), kDomain);
  // Measured 1.55e-4 between 2000 and 4000 cells, the same size as the planar error at 4000
  // cells against the exact solution (2.1e-4); 5e-4 bounds the reference's own error.
  EXPECT_LT(mediumToFine, 5e-4);
  // Differences shrink like the planar errors (measured ratio 1.87 per halving); 1.5 confirms
  // convergence without depending on the exact order.
  EXPECT_GT(coarseToMedium / mediumToFine, 1.5);
}

// Outermost r where the pressure exceeds the ambient value: the foot of the outgoing shock.
double shockRadius(const RadialRiemannSolution& s, double ambientPressure) {
  constexpr int samples = 20000;
  for (int k = samples; k >= 0; --k) {
    const double r = s.rMax() * k / samples;
    if (s.at(r).p > 1.01 * ambientPressure) return r;
  }
  return 0.0;
}

TEST(ExactRadialEuler, CircularSodHasCylindricalWaveStructure) {
  const RadialRiemannSolution solution = solveCircularSod(4000);
  const RiemannProblem planar(kSodHigh, kSodLow, kGamma);

  // The rarefaction head runs inward at the undisturbed sound speed, so the core
  // r < 0.4 - c t = 0.104 has not been reached yet; numerical precursors die off within a
  // few cells (measured: exact to the last bit below r = 0.0975).
  const double head = kDiscRadius + planar.leftHeadSpeed() * kEndTime;
  for (double r = 0.0; r < head - 0.01; r += 0.005) {
    const GasState s = solution.at(r);
    EXPECT_NEAR(s.rho, kSodHigh.rho, 1e-12) << "r = " << r;
    EXPECT_NEAR(s.p, kSodHigh.p, 1e-12) << "r = " << r;
  }

  // The outgoing shock is supersonic relative to the ambient gas but, because the shocked gas
  // spreads over a growing circumference, slower than the planar shock.
  const double rShock = shockRadius(solution, kSodLow.p);
  const double ambientSound = std::sqrt(kGamma * kSodLow.p / kSodLow.rho);
  EXPECT_GT(rShock, kDiscRadius + ambientSound * kEndTime);
  // Measured 0.814 against 0.838 planar: 95 cells apart, so 0.01 (40 cells) is a safe margin.
  EXPECT_LT(rShock, kDiscRadius + planar.rightHeadSpeed() * kEndTime - 0.01);
  for (double r = rShock + 0.005; r <= kDomain; r += 0.005) {
    const GasState s = solution.at(r);
    EXPECT_EQ(s.u, 0.0) << "r = " << r;
    EXPECT_EQ(s.p, kSodLow.p) << "r = " << r;
  }

  // Weaker shock: lower pressure, density and velocity behind it than in the planar star
  // region (measured p 0.244 vs 0.303). Sampled 0.01 (40 cells) behind the shock foot, past its
  // numerical width and ahead of the contact (near r = 0.62).
  const GasState shocked = solution.at(rShock - 0.01);
  EXPECT_GT(shocked.p, kSodLow.p);
  EXPECT_LT(shocked.p, 0.9 * planar.starPressure());
  EXPECT_GT(shocked.rho, kSodLow.rho);
  EXPECT_LT(shocked.rho, planar.starDensityRight());
  EXPECT_GT(shocked.u, 0.0);
  EXPECT_LT(shocked.u, planar.starVelocity());
  // Pressure outside the expanding disc never reaches the planar star pressure: the highest
  // value there is the one just behind the shock.
  double maxP = 0.0;
  for (double r = 0.45; r <= kDomain; r += 0.001) maxP = std::max(maxP, solution.at(r).p);
  EXPECT_LT(maxP, 0.9 * planar.starPressure());

  // Over-expansion: the diverging rarefaction accelerates the gas beyond the planar star
  // velocity and below the post-shock pressure, which is what forms the inward-facing secondary
  // shock near r = 0.42 (Toro 2009, sec. 17.1). Measured peak u = 1.125 vs u* = 0.927.
  double peakU = 0.0, minP = 1.0;
  for (double r = head; r <= 0.45; r += 0.001) {
    const GasState s = solution.at(r);
    peakU = std::max(peakU, s.u);
    minP = std::min(minP, s.p);
  }
  EXPECT_GT(peakU, 1.1 * planar.starVelocity());
  EXPECT_LT(minP, 0.8 * maxP);
}

TEST(ExactRadialEuler, AdvanceLandsExactlyOnRequestedTimes) {
  RadialRiemannSolution solution(3, kSodHigh, kSodLow, kDiscRadius, kGamma, kDomain, 100);
  EXPECT_EQ(solution.time(), 0.0);
  solution.advanceTo(0.1);
  EXPECT_EQ(solution.time(), 0.1);
  const int steps = solution.steps();
  solution.advanceTo(0.1);  // no-op
  EXPECT_EQ(solution.steps(), steps);
  solution.advanceTo(0.13);
  EXPECT_EQ(solution.time(), 0.13);
  EXPECT_THROW(solution.advanceTo(0.12), std::invalid_argument);
}

TEST(ExactRadialEuler, InvalidInputThrows) {
  auto make = [](int j, GasState in, double radius, double gamma, double rMax, int cells) {
    return RadialRiemannSolution(j, in, kSodLow, radius, gamma, rMax, cells);
  };
  EXPECT_THROW(make(0, kSodHigh, 0.4, kGamma, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(4, kSodHigh, 0.4, kGamma, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(2, {-1.0, 0.0, 1.0}, 0.4, kGamma, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(2, {1.0, 0.0, 0.0}, 0.4, kGamma, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(2, {1.0, NAN, 1.0}, 0.4, kGamma, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(2, kSodHigh, 0.4, 1.0, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(2, kSodHigh, 0.0, kGamma, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(2, kSodHigh, 1.0, kGamma, 1.0, 100), std::invalid_argument);
  EXPECT_THROW(make(2, kSodHigh, 0.4, kGamma, 1.0, 3), std::invalid_argument);
  const RadialRiemannSolution ok = make(2, kSodHigh, 0.4, kGamma, 1.0, 100);
  EXPECT_THROW(ok.at(-0.1), std::invalid_argument);
  EXPECT_THROW(ok.at(1.1), std::invalid_argument);
}


}  // namespace
