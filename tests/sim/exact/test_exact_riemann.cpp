// Tests of the exact Riemann solver (sim/exact/riemann.hpp) against Toro's published star
// states, an independent bisection solve, and the wave relations the sampled profile must obey.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/exact/riemann.hpp"

namespace {

using ejecta::exact::GasState;
using ejecta::exact::RiemannProblem;

constexpr double kGamma = 1.4;

double soundSpeed(const GasState& s, double gamma) { return std::sqrt(gamma * s.p / s.rho); }

struct ToroCase {
  const char* name;
  GasState left, right;
  double pStar, uStar, rhoStarL, rhoStarR;  // Toro (2009) Table 4.3, as printed
  double pTol, uTol, rhoLTol, rhoRTol;      // half a unit of the last printed digit (+ margin)
};

// Initial data: Toro Table 4.1 (tests 1-5, gamma = 1.4). Star values: Toro Table 4.3.
// Tolerances: each value is printed to a fixed number of digits, so |exact - printed| <= half a
// unit in the last digit; we allow 0.6 of a unit to absorb the rounding of the printed value.
const ToroCase kToroCases[] = {
    {"test1_sod",
     {1.0, 0.0, 1.0},
     {0.125, 0.0, 0.1},
     0.30313,
     0.92745,
     0.42632,
     0.26557,
     0.6e-5,
     0.6e-5,
     0.6e-5,
     0.6e-5},
    {"test2_123",
     {1.0, -2.0, 0.4},
     {1.0, 2.0, 0.4},
     0.00189,
     0.00000,
     0.02185,
     0.02185,
     0.6e-5,
     0.6e-5,
     0.6e-5,
     0.6e-5},
    {"test3_left_blast",
     {1.0, 0.0, 1000.0},
     {1.0, 0.0, 0.01},
     460.894,
     19.5975,
     0.57506,
     5.99924,
     0.6e-3,
     0.6e-4,
     0.6e-5,
     0.6e-5},
    {"test4_right_blast",
     {1.0, 0.0, 0.01},
     {1.0, 0.0, 100.0},
     46.0950,
     -6.19633,
     5.99242,
     0.57511,
     0.6e-4,
     0.6e-5,
     0.6e-5,
     0.6e-5},
    // Test 5 starts from the (rounded) star states of tests 3 and 4, and Toro's Newton stops at
    // a relative pressure change of 1e-6; his printed p* (1691.64) and u* (8.68975) differ from
    // the converged values (1691.647, 8.689774) by 4e-6 and 3e-6 relative. Tolerance: 1e-5
    // relative.
    {"test5_collision",
     {5.99924, 19.5975, 460.894},
     {5.99242, -6.19633, 46.0950},
     1691.64,
     8.68975,
     14.2823,
     31.0426,
     1e-5 * 1691.64,
     1e-5 * 8.68975,
     1e-5 * 14.2823,
     1e-5 * 31.0426},
};

TEST(ExactRiemann, ToroTable43StarStates) {
  for (const ToroCase& c : kToroCases) {
    SCOPED_TRACE(c.name);
    const RiemannProblem rp(c.left, c.right, kGamma);
    EXPECT_NEAR(rp.starPressure(), c.pStar, c.pTol);
    EXPECT_NEAR(rp.starVelocity(), c.uStar, c.uTol);
    EXPECT_NEAR(rp.starDensityLeft(), c.rhoStarL, c.rhoLTol);
    EXPECT_NEAR(rp.starDensityRight(), c.rhoStarR, c.rhoRTol);
  }
}

// Second, independent solve of the same pressure equation by plain bisection, written out
// here from Toro sec. 4.2 rather than sharing code with the solver.
double bisectionStarPressure(const GasState& l, const GasState& r, double g) {
  auto side = [g](double p, const GasState& s) {
    if (p > s.p) {
      const double a = 2.0 / ((g + 1.0) * s.rho);
      const double b = (g - 1.0) / (g + 1.0) * s.p;
      return (p - s.p) * std::sqrt(a / (p + b));
    }
    return 2.0 * soundSpeed(s, g) / (g - 1.0) * (std::pow(p / s.p, (g - 1.0) / (2.0 * g)) - 1.0);
  };
  auto f = [&](double p) { return side(p, l) + side(p, r) + r.u - l.u; };
  double lo = 0.0;
  double hi = 1.0;
  while (f(hi) < 0.0) hi *= 2.0;
  for (int i = 0; i < 2000 && hi - lo > 1e-16 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(ExactRiemann, NewtonAgreesWithBisection) {
  for (const ToroCase& c : kToroCases) {
    SCOPED_TRACE(c.name);
    const RiemannProblem rp(c.left, c.right, kGamma);
    // Both converge to round-off; f has slope O(1/(rho c)) so p* is fixed to ~1e-14 relative.
    EXPECT_NEAR(rp.starPressure(), bisectionStarPressure(c.left, c.right, kGamma),
                1e-12 * rp.starPressure());
  }
}

TEST(ExactRiemann, WaveTypesOfToroTests) {
  const RiemannProblem sod(kToroCases[0].left, kToroCases[0].right, kGamma);
  EXPECT_FALSE(sod.leftIsShock());
  EXPECT_TRUE(sod.rightIsShock());
  const RiemannProblem r123(kToroCases[1].left, kToroCases[1].right, kGamma);
  EXPECT_FALSE(r123.leftIsShock());
  EXPECT_FALSE(r123.rightIsShock());
  const RiemannProblem collision(kToroCases[4].left, kToroCases[4].right, kGamma);
  EXPECT_TRUE(collision.leftIsShock());
  EXPECT_TRUE(collision.rightIsShock());
}

void expectStateNear(const GasState& a, const GasState& b, double tol) {
  EXPECT_NEAR(a.rho, b.rho, tol * std::abs(b.rho));
  EXPECT_NEAR(a.u, b.u, tol * (std::abs(b.u) + soundSpeed(b, kGamma)));
  EXPECT_NEAR(a.p, b.p, tol * std::abs(b.p));
}

// Across a shock of speed s the fluxes of mass, momentum and energy balance (Rankine-Hugoniot)
// in the frame of the shock: [rho (u - s)] = 0, [rho u (u - s) + p] = 0, [E (u - s) + p u] = 0.
void expectRankineHugoniot(const GasState& a, const GasState& b, double s) {
  auto energy = [](const GasState& q) { return q.p / (kGamma - 1.0) + 0.5 * q.rho * q.u * q.u; };
  const double scaleMass = a.rho * std::abs(a.u - s) + b.rho * std::abs(b.u - s);
  EXPECT_NEAR(a.rho * (a.u - s), b.rho * (b.u - s), 1e-12 * scaleMass);
  const double scaleMom = a.p + b.p + a.rho * a.u * a.u + b.rho * b.u * b.u;
  EXPECT_NEAR(a.rho * a.u * (a.u - s) + a.p, b.rho * b.u * (b.u - s) + b.p, 1e-12 * scaleMom);
  const double scaleEnergy =
      (energy(a) + a.p + energy(b) + b.p) * (std::abs(a.u) + std::abs(b.u) + std::abs(s));
  EXPECT_NEAR(energy(a) * (a.u - s) + a.p * a.u, energy(b) * (b.u - s) + b.p * b.u,
              1e-12 * scaleEnergy);
}

TEST(ExactRiemann, SodProfileStructure) {
  const GasState left{1.0, 0.0, 1.0};
  const GasState right{0.125, 0.0, 0.1};
  const RiemannProblem rp(left, right, kGamma);
  const double cL = soundSpeed(left, kGamma);
  const double pStar = rp.starPressure();
  const double uStar = rp.starVelocity();

  // Fan edges: head at uL - cL, tail at u* - c*L with c*L from isentropic expansion.
  EXPECT_DOUBLE_EQ(rp.leftHeadSpeed(), -cL);
  const double cStarL = cL * std::pow(pStar / left.p, (kGamma - 1.0) / (2.0 * kGamma));
  EXPECT_NEAR(rp.leftTailSpeed(), uStar - cStarL, 1e-14);
  // Right shock speed from the shock Mach number relation (Toro sec. 4.4.1), written out here.
  const double cR = soundSpeed(right, kGamma);
  const double shockSpeed =
      right.u + cR * std::sqrt((kGamma + 1.0) / (2.0 * kGamma) * pStar / right.p +
                               (kGamma - 1.0) / (2.0 * kGamma));
  EXPECT_NEAR(rp.rightHeadSpeed(), shockSpeed, 1e-14);  // same closed form: round-off only
  EXPECT_DOUBLE_EQ(rp.rightHeadSpeed(), rp.rightTailSpeed());

  // Undisturbed states outside the waves, star states between them.
  constexpr double eps = 1e-9;
  expectStateNear(rp.sample(-10.0), left, 0.0);
  expectStateNear(rp.sample(rp.leftHeadSpeed() - eps), left, 0.0);
  expectStateNear(rp.sample(rp.leftTailSpeed() + eps), GasState{rp.starDensityLeft(), uStar, pStar},
                  0.0);
  expectStateNear(rp.sample(uStar + eps), GasState{rp.starDensityRight(), uStar, pStar}, 0.0);
  expectStateNear(rp.sample(rp.rightHeadSpeed() - eps),
                  GasState{rp.starDensityRight(), uStar, pStar}, 0.0);
  expectStateNear(rp.sample(rp.rightHeadSpeed() + eps), right, 0.0);
  expectStateNear(rp.sample(10.0), right, 0.0);

  // Fan is continuous at both edges (within the O(eps) change of a linear profile).
  expectStateNear(rp.sample(rp.leftHeadSpeed() + eps), left, 1e-8);
  expectStateNear(rp.sample(rp.leftTailSpeed() - eps), GasState{rp.starDensityLeft(), uStar, pStar},
                  1e-8);

  // Contact: pressure and velocity continuous, density jumps.
  const GasState a = rp.sample(uStar - eps);
  const GasState b = rp.sample(uStar + eps);
  EXPECT_EQ(a.p, b.p);
  EXPECT_EQ(a.u, b.u);
  EXPECT_GT(a.rho, b.rho);

  // Right shock satisfies the Rankine-Hugoniot conditions.
  expectRankineHugoniot(rp.sample(rp.rightHeadSpeed() - eps), rp.sample(rp.rightHeadSpeed() + eps),
                        rp.rightHeadSpeed());
}

TEST(ExactRiemann, LeftFanIsASimpleWave) {
  // Inside the left fan: C- characteristics are straight lines, u - c = x/t; the Riemann
  // invariant u + 2c/(gamma-1) and the entropy p/rho^gamma equal their left-state values.
  const GasState left{1.0, 0.0, 1.0};
  const RiemannProblem rp(left, GasState{0.125, 0.0, 0.1}, kGamma);
  const double cL = soundSpeed(left, kGamma);
  const double invariant = left.u + 2.0 * cL / (kGamma - 1.0);
  const double entropy = left.p / std::pow(left.rho, kGamma);
  for (int i = 1; i < 10; ++i) {
    const double xi = rp.leftHeadSpeed() + (rp.leftTailSpeed() - rp.leftHeadSpeed()) * i / 10.0;
    const GasState s = rp.sample(xi);
    const double c = soundSpeed(s, kGamma);
    EXPECT_NEAR(s.u - c, xi, 1e-14);  // closed-form expressions: round-off only
    EXPECT_NEAR(s.u + 2.0 * c / (kGamma - 1.0), invariant, 1e-13);
    EXPECT_NEAR(s.p / std::pow(s.rho, kGamma), entropy, 1e-13);
  }
}

TEST(ExactRiemann, RightFanIsASimpleWave) {
  // Toro test 2 (two rarefactions): in the right fan u + c = x/t, u - 2c/(gamma-1) = const.
  const GasState right{1.0, 2.0, 0.4};
  const RiemannProblem rp(GasState{1.0, -2.0, 0.4}, right, kGamma);
  const double cR = soundSpeed(right, kGamma);
  EXPECT_DOUBLE_EQ(rp.rightHeadSpeed(), right.u + cR);
  const double invariant = right.u - 2.0 * cR / (kGamma - 1.0);
  for (int i = 1; i < 10; ++i) {
    const double xi = rp.rightTailSpeed() + (rp.rightHeadSpeed() - rp.rightTailSpeed()) * i / 10.0;
    const GasState s = rp.sample(xi);
    const double c = soundSpeed(s, kGamma);
    EXPECT_NEAR(s.u + c, xi, 1e-14);
    EXPECT_NEAR(s.u - 2.0 * c / (kGamma - 1.0), invariant, 1e-13);
  }
  // Symmetric data: the solution is symmetric about x = 0.
  EXPECT_EQ(rp.starVelocity(), 0.0);
  const GasState a = rp.sample(-0.7);
  const GasState b = rp.sample(0.7);
  EXPECT_NEAR(a.rho, b.rho, 1e-14);
  EXPECT_NEAR(a.u, -b.u, 1e-14);
  EXPECT_NEAR(a.p, b.p, 1e-14);
}

TEST(ExactRiemann, TwoShocksSatisfyRankineHugoniot) {
  const ToroCase& c = kToroCases[4];
  const RiemannProblem rp(c.left, c.right, kGamma);
  constexpr double eps = 1e-9;
  expectRankineHugoniot(rp.sample(rp.leftHeadSpeed() - eps), rp.sample(rp.leftHeadSpeed() + eps),
                        rp.leftHeadSpeed());
  expectRankineHugoniot(rp.sample(rp.rightHeadSpeed() - eps), rp.sample(rp.rightHeadSpeed() + eps),
                        rp.rightHeadSpeed());
  // Wave ordering: left shock < contact < right shock.
  EXPECT_LT(rp.leftHeadSpeed(), rp.starVelocity());
  EXPECT_LT(rp.starVelocity(), rp.rightHeadSpeed());
}

TEST(ExactRiemann, MirrorSymmetry) {
  // Reflecting x -> -x swaps the states and negates velocities; p* is unchanged.
  const ToroCase& c = kToroCases[0];
  const RiemannProblem rp(c.left, c.right, kGamma);
  const RiemannProblem mirrored(GasState{c.right.rho, -c.right.u, c.right.p},
                                GasState{c.left.rho, -c.left.u, c.left.p}, kGamma);
  EXPECT_NEAR(mirrored.starPressure(), rp.starPressure(), 1e-14);
  EXPECT_NEAR(mirrored.starVelocity(), -rp.starVelocity(), 1e-14);
  EXPECT_NEAR(mirrored.starDensityLeft(), rp.starDensityRight(), 1e-14);
  for (double xi : {-1.5, -0.9, -0.3, 0.2, 1.1, 1.8}) {
    const GasState a = rp.sample(xi);
    const GasState b = mirrored.sample(-xi);
    EXPECT_NEAR(a.rho, b.rho, 1e-13);
    EXPECT_NEAR(a.u, -b.u, 1e-13);
    EXPECT_NEAR(a.p, b.p, 1e-13);
  }
}

TEST(ExactRiemann, UniformStateIsUnchanged) {
  const GasState s{2.0, 0.3, 5.0};
  const RiemannProblem rp(s, s, 5.0 / 3.0);
  EXPECT_NEAR(rp.starPressure(), s.p, 1e-14 * s.p);
  EXPECT_NEAR(rp.starVelocity(), s.u, 1e-14);
  for (double xi : {-5.0, -1.0, 0.0, 0.3, 1.0, 5.0}) {
    const GasState q = rp.sample(xi);
    EXPECT_NEAR(q.rho, s.rho, 1e-13);
    EXPECT_NEAR(q.u, s.u, 1e-13);
    EXPECT_NEAR(q.p, s.p, 1e-13);
  }
}

TEST(ExactRiemann, VacuumGenerationThrows) {
  // uR - uL = 10 exceeds 2 (cL + cR)/(gamma - 1) = 7.48: the rarefactions separate.
  EXPECT_THROW(RiemannProblem(GasState{1.0, -5.0, 0.4}, GasState{1.0, 5.0, 0.4}, kGamma),
               std::domain_error);
  // Just below the threshold the solver still works and p* is tiny but positive.
  const double c = std::sqrt(kGamma * 0.4);
  const double critical = 2.0 * 2.0 * c / (kGamma - 1.0);
  const RiemannProblem nearVacuum(GasState{1.0, -0.49 * critical, 0.4},
                                  GasState{1.0, 0.49 * critical, 0.4}, kGamma);
  EXPECT_GT(nearVacuum.starPressure(), 0.0);
  EXPECT_LT(nearVacuum.starPressure(), 1e-6);
}

TEST(ExactRiemann, InvalidInputThrows) {
  const GasState ok{1.0, 0.0, 1.0};
  EXPECT_THROW(RiemannProblem(GasState{0.0, 0.0, 1.0}, ok, kGamma), std::invalid_argument);
  EXPECT_THROW(RiemannProblem(ok, GasState{1.0, 0.0, -1.0}, kGamma), std::invalid_argument);
  EXPECT_THROW(RiemannProblem(ok, GasState{1.0, NAN, 1.0}, kGamma), std::invalid_argument);
  EXPECT_THROW(RiemannProblem(ok, ok, 1.0), std::invalid_argument);
}

}  // namespace
