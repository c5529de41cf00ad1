// Tests of the Sedov-Taylor-von Neumann solution (sim/exact/sedov.hpp): published energy
// constants and shock radii, the closed-form spherical solution of Landau & Lifshitz, jump
// conditions, and conservation integrals of the tabulated profile.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "sim/exact/sedov.hpp"

namespace {

using ejecta::exact::SedovSolution;
using ejecta::exact::SedovState;

// Composite 5-point Gauss-Legendre quadrature of f over [a, b] with n panels.
double integrate(const std::function<double(double)>& f, double a, double b, int n) {
  static constexpr std::array<double, 5> x{0.0, -0.5384693101056831, 0.5384693101056831,
                                           -0.9061798459386640, 0.9061798459386640};
  static constexpr std::array<double, 5> w{0.5688888888888889, 0.4786286704993665,
                                           0.4786286704993665, 0.2369268850561891,
                                           0.2369268850561891};
  const double h = (b - a) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double mid = a + (i + 0.5) * h;
    for (std::size_t k = 0; k < x.size(); ++k) sum += w[k] * f(mid + 0.5 * h * x[k]);
  }
  return 0.5 * h * sum;
}

double measure(int j, double r) {  // sigma_j r^(j-1): slab (both sides), per length, sphere
  switch (j) {
    case 1:
      return 2.0;
    case 2:
      return 2.0 * std::numbers::pi * r;
    default:
      return 4.0 * std::numbers::pi * r * r;
  }
}

// --- Published values -----------------------------------------------------------------------

TEST(ExactSedov, KammTimmesSphericalEnergy) {
  // Kamm & Timmes (2007), LA-UR-07-2849: gamma = 1.4, rho0 = 1, E = 0.851072 puts the spherical
  // shock at r = 1 at t = 1, i.e. alpha = 0.851072. Printed to 6 significant figures: 1e-6.
  const SedovSolution s(3, 1.4, 0.851072, 1.0);
  EXPECT_NEAR(s.alpha(), 0.851072, 1e-6 * 0.851072);
  EXPECT_NEAR(s.shockRadius(1.0), 1.0, 1e-6);
}

TEST(ExactSedov, KammTimmesCylindricalEnergy) {
  // Kamm & Timmes (2007) cylindrical standard case, E = 0.311357 per unit length, gamma = 1.4,
  // rho0 = 1: the shock is at r = 0.75 at t = 1 (as documented with ExactPack, which uses their
  // solver). Our alpha = 0.9840740 (confirmed to 1e-11 by a second, independent integration,
  // docs/exact_solutions.md) puts it at 0.749994: their E is 3.3e-5 relative below ours, beyond
  // its 6 printed digits, presumably their quadrature tolerance. Allowed: 5e-5 in E, so
  // 1.25e-5 in R.
  const SedovSolution s(2, 1.4, 0.311357, 1.0);
  EXPECT_NEAR(s.shockRadius(1.0), 0.75, 1.25e-5 * 0.75);
  EXPECT_NEAR(s.alpha(), 0.311357 / std::pow(0.75, 4), 5e-5 * s.alpha());
}

TEST(ExactSedov, KammTimmesPlanarEnergy) {
  // Kamm & Timmes (2007) planar standard case, E = 0.0673185, gamma = 1.4, rho0 = 1: shock at
  // x = 0.5 at t = 1 (ExactPack documentation). Their planar energy integral is over x > 0 only
  // (dV = dx), so in our whole-slab convention E = 2 * 0.0673185. Our alpha (1.0774856, two
  // independent integrations agree to 1e-11) gives x = 0.49994: their E is 3.6e-4 relative off
  // ours, the largest of their three cases. Allowed: 2e-4 relative in R (1.2e-4 observed).
  const SedovSolution s(1, 1.4, 2.0 * 0.0673185, 1.0);
  EXPECT_NEAR(s.shockRadius(1.0), 0.5, 2e-4 * 0.5);
}

TEST(ExactSedov, SphExaBenchmarkShockRadius) {
  // SPH-EXA Sedov benchmark: gamma = 5/3, E = 1, rho0 = 1, t = 0.05: shock radius ~ 0.3475
  // (quoted to 4 significant figures: half a unit = 5e-5).
  const SedovSolution s(3, 5.0 / 3.0, 1.0, 1.0);
  EXPECT_NEAR(s.shockRadius(0.05), 0.3475, 5e-5);
}

// --- Closed-form spherical solution --------------------------------------------------------

// Landau & Lifshitz, "Fluid Mechanics" (2nd ed.), sec. 106: for j = 3 with v = (2r/5t) V,
// lambda^5 = [(g+1)V/2]^-2 [(g+1)/(7-g) (5-(3g-1)V)]^n1 [(g+1)/(g-1) (gV-1)]^n2 and
// G/G1 = [(g+1)/(g-1) (gV-1)]^n3 [(g+1)/(7-g) (5-(3g-1)V)]^n4 [(g+1)/(g-1) (1-V)]^n5, with
// n1 = -(13g^2-7g+12)/((3g-1)(2g+1)), n2 = 5(g-1)/(2g+1), n3 = 3/(2g+1), n4 = -n1/(2-g),
// n5 = -2/(2-g); V runs from 2/(g+1) at the shock to 1/g at the centre.
struct ClosedFormPoint {
  double lambda, density, velocity;  // density / rho1, v t / r
};

ClosedFormPoint landauLifshitzSpherical(double g, double vLL) {
  const double n1 = -(13.0 * g * g - 7.0 * g + 12.0) / ((3.0 * g - 1.0) * (2.0 * g + 1.0));
  const double n2 = 5.0 * (g - 1.0) / (2.0 * g + 1.0);
  const double n3 = 3.0 / (2.0 * g + 1.0);
  const double n4 = -n1 / (2.0 - g);
  const double n5 = -2.0 / (2.0 - g);
  const double a = (g + 1.0) / (7.0 - g) * (5.0 - (3.0 * g - 1.0) * vLL);
  const double b = (g + 1.0) / (g - 1.0) * (g * vLL - 1.0);
  const double c = (g + 1.0) / (g - 1.0) * (1.0 - vLL);
  const double lambda5 = std::pow(0.5 * (g + 1.0) * vLL, -2.0) * std::pow(a, n1) * std::pow(b, n2);
  return {std::pow(lambda5, 0.2), std::pow(b, n3) * std::pow(a, n4) * std::pow(c, n5), 0.4 * vLL};
}

TEST(ExactSedov, MatchesLandauLifshitzClosedForm) {
  for (double g : {1.4, 5.0 / 3.0}) {
    SCOPED_TRACE(g);
    const SedovSolution s(3, g, 1.0, 1.0);
    const double t = 1.0;
    const double radius = s.shockRadius(t);
    const double vShock = 2.0 / (g + 1.0);
    const double vCentre = 1.0 / g;
    for (double f : {0.999, 0.99, 0.95, 0.8, 0.6, 0.4, 0.2, 0.1, 0.02}) {
      const ClosedFormPoint ref = landauLifshitzSpherical(g, vCentre + f * (vShock - vCentre));
      const SedovState st = s.at(ref.lambda * radius, t);
      // The table is accurate to ~1e-9 relative away from the origin (docs); allow 1e-8.
      EXPECT_NEAR(st.rho / s.postShockDensity(), ref.density, 1e-8 * ref.density);
      EXPECT_NEAR(st.v * t / (ref.lambda * radius), ref.velocity, 1e-8 * ref.velocity);
    }
  }
}

// --- Structure of the solution ---------------------------------------------------------------

TEST(ExactSedov, StrongShockJumpConditions) {
  for (int j = 1; j <= 3; ++j) {
    const double g = 1.4;
    const double rho0 = 2.5;
    const SedovSolution s(j, g, 3.0, rho0);
    const double t = 0.7;
    const double radius = s.shockRadius(t);
    const double speed = s.shockSpeed(t);
    EXPECT_NEAR(speed, 2.0 / (j + 2.0) * radius / t, 1e-15 * speed);
    // Rankine-Hugoniot for a strong shock into gas at rest with p = 0: closed forms, so the
    // table node at the shock must reproduce them to round-off (1e-13).
    const SedovState behind = s.at(radius, t);
    EXPECT_NEAR(behind.rho, rho0 * (g + 1.0) / (g - 1.0), 1e-13 * behind.rho);
    EXPECT_NEAR(behind.v, 2.0 * speed / (g + 1.0), 1e-13 * behind.v);
    EXPECT_NEAR(behind.p, 2.0 * rho0 * speed * speed / (g + 1.0), 1e-13 * behind.p);
    EXPECT_DOUBLE_EQ(s.postShockDensity(), rho0 * (g + 1.0) / (g - 1.0));
    EXPECT_NEAR(s.postShockPressure(t), behind.p, 1e-13 * behind.p);
    EXPECT_NEAR(s.postShockVelocity(t), behind.v, 1e-13 * behind.v);
    // Mass flux through the shock: rho0 U = rho1 (U - v1).
    EXPECT_NEAR(rho0 * speed, behind.rho * (speed - behind.v), 1e-13 * rho0 * speed);
    // Ahead of the shock: undisturbed.
    const SedovState ahead = s.at(radius * (1.0 + 1e-12), t);
    EXPECT_EQ(ahead.rho, rho0);
    EXPECT_EQ(ahead.v, 0.0);
    EXPECT_EQ(ahead.p, 0.0);
  }
}

struct Case {
  int j;
  double gamma;
};
constexpr Case kCases[] = {{1, 1.2}, {1, 1.4}, {1, 5.0 / 3.0}, {1, 3.0},
                           {2, 1.2}, {2, 1.4}, {2, 5.0 / 3.0}, {2, 3.0},
                           {3, 1.2}, {3, 1.4}, {3, 5.0 / 3.0}, {3, 3.0}};

TEST(ExactSedov, ProfileCarriesTheBlastEnergy) {
  // Kinetic + internal energy of the profile, integrated with the j-dependent measure, equals E.
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << "j=" << c.j << " gamma=" << c.gamma);
    const double energy = 7.0;
    const SedovSolution s(c.j, c.gamma, energy, 1.3);
    const double t = 0.4;
    const double total = integrate(
        [&](double r) {
          const SedovState st = s.at(r, t);
          return (0.5 * st.rho * st.v * st.v + st.p / (c.gamma - 1.0)) * measure(c.j, r);
        },
        0.0, s.shockRadius(t), 4000);
    // Quadrature and table errors are ~1e-9 (docs); the brief asks for 1e-5; check 1e-7.
    EXPECT_NEAR(total, energy, 1e-7 * energy);
  }
}

TEST(ExactSedov, ProfileHoldsTheSweptUpMass) {
  // All mass once inside R(t) is now in the profile: int rho dV = rho0 V_j(R).
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << "j=" << c.j << " gamma=" << c.gamma);
    const double rho0 = 1.3;
    const SedovSolution s(c.j, c.gamma, 7.0, rho0);
    const double t = 0.4;
    const double radius = s.shockRadius(t);
    const double mass =
        integrate([&](double r) { return s.at(r, t).rho * measure(c.j, r); }, 0.0, radius, 4000);
    const double swept = rho0 * measure(c.j, radius) * radius / c.j;
    EXPECT_NEAR(mass, swept, 1e-7 * swept);  // as above: ~1e-9 expected
  }
}

TEST(ExactSedov, EntropyMatchesShockHistory) {
  // Each shell keeps the entropy p/rho^gamma it got when shocked. A shell with a fraction
  // mu = m(r)/m(R) of the swept mass was shocked at radius R mu^(1/j), where the post-shock
  // p/rho^gamma was larger by mu^-1 (p1 ~ U^2 ~ R^-j). So p/rho^gamma = K1 / mu.
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << "j=" << c.j << " gamma=" << c.gamma);
    const SedovSolution s(c.j, c.gamma, 1.0, 1.0);
    const double t = 1.0;
    const double radius = s.shockRadius(t);
    const double k1 = s.postShockPressure(t) / std::pow(s.postShockDensity(), c.gamma);
    const double totalMass = radius * measure(c.j, radius) / c.j;  // rho0 = 1
    for (double lambda : {0.4, 0.7, 0.9, 0.99}) {
      const double r = lambda * radius;
      const double mu =
          integrate([&](double x) { return s.at(x, t).rho * measure(c.j, x); }, 0.0, r, 4000) /
          totalMass;
      const SedovState st = s.at(r, t);
      EXPECT_NEAR(st.p / std::pow(st.rho, c.gamma), k1 / mu, 1e-7 * k1 / mu);  // ~1e-9 expected
    }
  }
}

TEST(ExactSedov, ProfilesAreMonotone) {
  // Density, velocity and pressure all rise from the centre to the shock in the standard case.
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << "j=" << c.j << " gamma=" << c.gamma);
    const SedovSolution s(c.j, c.gamma, 1.0, 1.0);
    const double radius = s.shockRadius(1.0);
    SedovState prev = s.at(0.0, 1.0);
    constexpr int n = 20000;
    for (int i = 1; i <= n; ++i) {
      const SedovState st = s.at(radius * i / (n + 1.0), 1.0);
      EXPECT_GE(st.rho, prev.rho);
      EXPECT_GE(st.v, prev.v);
      // Near the centre p is flat to ~1e-10: allow that much interpolation noise.
      EXPECT_GE(st.p, prev.p * (1.0 - 1e-9));
      prev = st;
    }
  }
}

TEST(ExactSedov, CentreLimit) {
  const SedovSolution s(3, 1.4, 1.0, 1.0);
  const double radius = s.shockRadius(1.0);
  const SedovState centre = s.at(0.0, 1.0);
  EXPECT_EQ(centre.rho, 0.0);
  EXPECT_EQ(centre.v, 0.0);
  EXPECT_GT(centre.p, 0.0);
  EXPECT_TRUE(std::isinf(centre.e()));
  // Continuous approach to the centre (pressure flat to round-off, density -> 0 like r^7.5).
  const SedovState near = s.at(1e-6 * radius, 1.0);
  EXPECT_NEAR(near.p, centre.p, 1e-9 * centre.p);
  EXPECT_LT(near.rho, 1e-40);
  // Central pressure ratio, Sedov's spherical gamma = 1.4 solution: p(0)/p1 = 0.3655 (computed
  // here; the book's graphs show ~0.37). Regression guard at the 1e-3 level.
  EXPECT_NEAR(centre.p / s.postShockPressure(1.0), 0.3655, 1e-3);
}

TEST(ExactSedov, SelfSimilarScaling) {
  // Doubling t at fixed E: R grows by 2^(2/(j+2)); the profile in r/R is unchanged for rho and
  // scales with (R/t) for v and (R/t)^2 for p. Doubling rho0 at fixed E shrinks R by
  // 2^(-1/(j+2)). Exact identities of the implementation up to round-off.
  for (int j = 1; j <= 3; ++j) {
    const SedovSolution s(j, 1.4, 2.0, 1.0);
    const SedovSolution dense(j, 1.4, 2.0, 2.0);
    const double t1 = 0.3;
    const double t2 = 0.6;
    const double r1 = s.shockRadius(t1);
    const double r2 = s.shockRadius(t2);
    EXPECT_NEAR(r2 / r1, std::pow(2.0, 2.0 / (j + 2.0)), 1e-14);
    EXPECT_NEAR(dense.shockRadius(t1) / r1, std::pow(2.0, -1.0 / (j + 2.0)), 1e-14);
    EXPECT_NEAR(s.timeOfShockRadius(r1), t1, 1e-14);
    for (double lambda : {0.2, 0.5, 0.8, 0.97}) {
      const SedovState a = s.at(lambda * r1, t1);
      const SedovState b = s.at(lambda * r2, t2);
      const double k = (r2 / t2) / (r1 / t1);
      EXPECT_NEAR(b.rho, a.rho, 1e-12 * a.rho);
      EXPECT_NEAR(b.v, a.v * k, 1e-12 * b.v);
      EXPECT_NEAR(b.p, a.p * k * k, 1e-12 * b.p);
    }
  }
}

TEST(ExactSedov, InvalidInputThrows) {
  EXPECT_THROW(SedovSolution(0, 1.4, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(SedovSolution(4, 1.4, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(SedovSolution(3, 1.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(SedovSolution(3, 7.0, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(SedovSolution(3, 1.4, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(SedovSolution(3, 1.4, 1.0, -1.0), std::invalid_argument);
  const SedovSolution s(3, 1.4, 1.0, 1.0);
  EXPECT_THROW((void)s.at(-0.1, 1.0), std::invalid_argument);
  EXPECT_THROW((void)s.at(0.1, 0.0), std::invalid_argument);
  EXPECT_THROW((void)s.shockRadius(NAN), std::invalid_argument);
}

}  // namespace
