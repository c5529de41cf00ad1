// Shock (Mie-Grueneisen) and polynomial EOS: Hugoniot identity, continuity at mu = 0, sound
// speed at the reference state, exact energy inverse, batched = single point, c^2 > 0.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/eos/mie_gruneisen.hpp"

namespace ejecta {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// The Mie-Grueneisen law referenced to the Hugoniot with rho Gamma = rho0 (gamma0 + a mu) gives
// P(rho_H, u_H) = P_H identically, for any a and for the cubic fit as well as the linear one
// (docs/eos_shock_jwl.md, "Hugoniot identity"). Only round-off separates the two sides.
void expectHugoniotIdentity(const std::string& name, double upMax) {
  const ShockMaterial& m = shockMaterial(name);
  const MieGruneisen eos(m);
  for (double up = 0.05 * upMax; up <= upMax; up += 0.05 * upMax) {
    const HugoniotState h = hugoniotState(m, up);
    ASSERT_LT(h.rho / m.rho0 - 1.0, eos.maxCompression()) << name << " up " << up;
    // 1e-10: the identity is exact; the two sides differ by a few ulps times the cancellation in
    // 1 - (S1-1) mu - ... (at most ~10x here).
    EXPECT_LT(rel(eos.pressure(h.rho, h.u), h.P), 1e-10) << name << " up = " << up;
  }
}

TEST(MieGruneisen, HugoniotIdentityLinearAl2024) { expectHugoniotIdentity("Al-2024", 8000.0); }

TEST(MieGruneisen, HugoniotIdentityLinearCopper) { expectHugoniotIdentity("copper", 5000.0); }

TEST(MieGruneisen, HugoniotIdentityCubicWater) { expectHugoniotIdentity("water", 4000.0); }

TEST(MieGruneisen, CubicHugoniotSolverSatisfiesTheFit) {
  const ShockMaterial& m = shockMaterial("water");
  for (double up : {100.0, 1000.0, 3000.0}) {
    const double us = hugoniotShockVelocity(m, up);
    const double fit = m.c0 + m.s1 * up + m.s2 * up * up / us + m.s3 * up * up * up / (us * us);
    EXPECT_LT(rel(us, fit), 1e-13) << up;  // Newton converged to round-off
  }
}

TEST(MieGruneisen, LinearHugoniotIsUsEqualsC0PlusSUp) {
  const ShockMaterial& m = shockMaterial("Al-2024");
  for (double up : {500.0, 1000.0, 2000.0})
    EXPECT_LT(rel(hugoniotShockVelocity(m, up), m.c0 + m.s1 * up), 1e-15) << up;
}

TEST(MieGruneisen, SoundSpeedAtReferenceStateIsC0) {
  for (const std::string name : {"Al-2024", "copper", "water", "Al-1100"}) {
    const ShockMaterial& m = shockMaterial(name);
    const MieGruneisen eos(m);
    EXPECT_EQ(eos.pressure(m.rho0, 0.0), 0.0) << name;
    EXPECT_LT(rel(eos.soundSpeed(m.rho0, 0.0), m.c0), 1e-15) << name;  // c^2 = C0^2 exactly
  }
}

TEST(MieGruneisen, PressureAndSoundSpeedContinuousAtMuZero) {
  for (const std::string name : {"Al-2024", "water", "copper"}) {
    const ShockMaterial& m = shockMaterial(name);
    const MieGruneisen eos(m);
    const double eps = 1e-9;
    for (double u : {0.0, 1e4, 1e6}) {
      const double lo = m.rho0 * (1.0 - eps), hi = m.rho0 * (1.0 + eps);
      // Both branches share value and slope at mu = 0, so across 2e-9 in mu the change is
      // ~1e-9 of the dominant scale (rho0 C0^2 for P, C0 for c).
      EXPECT_LT(std::abs(eos.pressure(hi, u) - eos.pressure(lo, u)),
                1e-8 * m.rho0 * m.c0 * m.c0) << name << " u " << u;
      EXPECT_LT(rel(eos.soundSpeed(hi, u), eos.soundSpeed(lo, u)), 1e-8) << name << " u " << u;
    }
  }
}

TEST(MieGruneisen, SpecificEnergyRoundTrip) {
  for (const std::string name : {"Al-2024", "water", "copper", "Al-1100"}) {
    const ShockMaterial& m = shockMaterial(name);
    const MieGruneisen eos(m);
    for (double x : {0.5, 0.8, 0.99, 1.0, 1.01, 1.3, 1.8})
      for (double u : {0.0, 1e3, 1e5, 1e7}) {
        const double rho = x * m.rho0;
        const double P = eos.pressure(rho, u);
        // u = (P - P(rho,0)) / (rho Gamma): the subtraction loses log10(|P|/|rho Gamma u|)
        // digits; 1e-6 of the larger of u and P/(rho0 gamma0) bounds that with margin.
        const double scale = std::max(u, std::abs(P) / (m.rho0 * m.gamma0));
        EXPECT_LE(std::abs(eos.specificEnergy(rho, P) - u), 1e-9 * scale)
            << name << " rho/rho0 " << x << " u " << u;
      }
  }
}

TEST(MieGruneisen, SpecificEnergyRejectsNonPositiveDensity) {
  const MieGruneisen eos(shockMaterial("Al-2024"));
  EXPECT_THROW(eos.specificEnergy(0.0, 1e9), std::domain_error);
  EXPECT_THROW(eos.specificEnergy(-1.0, 1e9), std::domain_error);
}

TEST(MieGruneisen, BatchedEqualsSinglePoint) {
  const MieGruneisen eos(shockMaterial("water"));
  std::vector<double> rho, u;
  for (int i = 0; i < 40; ++i) {
    rho.push_back(1000.0 * (0.7 + 0.03 * i));
    u.push_back(1e4 * i);
  }
  std::vector<double> P(rho.size(), -1.0), cs(rho.size(), -1.0);
  std::vector<std::size_t> idx;
  for (std::size_t i = 1; i < rho.size(); i += 3) idx.push_back(i);  // a strided subset
  eos.evaluate(rho.data(), u.data(), P.data(), cs.data(), idx.data(), idx.size());
  for (std::size_t i = 0; i < rho.size(); ++i) {
    if (i % 3 == 1) {
      EXPECT_EQ(P[i], eos.pressure(rho[i], u[i]));  // same code path: bitwise equal
      EXPECT_EQ(cs[i], eos.soundSpeed(rho[i], u[i]));
    } else {
      EXPECT_EQ(P[i], -1.0);  // untouched outside the index list
      EXPECT_EQ(cs[i], -1.0);
    }
  }
}

TEST(MieGruneisen, SoundSpeedSquaredPositiveOnDenseGrid) {
  for (const std::string name : {"Al-2024", "water", "copper", "Al-1100"}) {
    const ShockMaterial& m = shockMaterial(name);
    const MieGruneisen eos(m);
    // Near the reference density: mild tension to 30% compression, any u >= 0.
    for (int i = 0; i <= 100; ++i) {
      const double mu = -0.2 + 0.5 * i / 100.0;
      for (int j = 0; j <= 50; ++j) {
        const double u = 2e7 * j / 50.0;
        EXPECT_GT(eos.soundSpeedSquared(m.rho0 * (1.0 + mu), u), 0.0)
            << name << " mu " << mu << " u " << u;
      }
    }
    // Strong compression: on the Hugoniot (up to 6 km/s) and hotter. Colder states at these
    // densities lie below the 0 K isotherm, where the fit's u = 0 curve bends to negative
    // pressure (1 + (1 - gamma0/2) mu - (a/2) mu^2 < 0) and c^2 < 0 is expected.
    for (int i = 1; i <= 120; ++i) {
      const HugoniotState h = hugoniotState(m, 50.0 * i);
      for (int j = 0; j <= 20; ++j) {
        const double u = h.u + 2e7 * j / 20.0;
        EXPECT_GT(eos.soundSpeedSquared(h.rho, u), 0.0) << name << " up " << h.up << " u " << u;
      }
    }
    // Anywhere at all (deep tension, past the limiting compression, negative u): finite, > 0.
    for (double x : {1e-9, 1e-3, 0.1, 0.5, 1.0, 3.0, 5.0, 100.0})
      for (double u : {-1e7, 0.0, 1e9}) {
        const double c = eos.soundSpeed(x * m.rho0, u);
        EXPECT_TRUE(std::isfinite(c) && c > 0.0) << name << " x " << x << " u " << u;
        EXPECT_TRUE(std::isfinite(eos.pressure(x * m.rho0, u))) << name << " x " << x;
      }
  }
}

TEST(MieGruneisen, LibraryLookupListsNames) {
  EXPECT_EQ(shockMaterial("Al-2024").rho0, 2785.0);
  try {
    shockMaterial("unobtainium");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    for (const auto& n : shockMaterialNames()) EXPECT_NE(msg.find(n), std::string::npos) << n;
  }
  for (const auto& n : shockMaterialNames()) EXPECT_FALSE(shockMaterial(n).source.empty()) << n;
}

TEST(MieGruneisen, RejectsBadParameters) {
  ShockMaterial m = shockMaterial("Al-2024");
  m.c0 = 0.0;
  EXPECT_THROW(MieGruneisen{m}, std::invalid_argument);
}

TEST(PolynomialEos, MatchesMieGruneisenToThirdOrder) {
  for (const std::string name : {"Al-2024", "water", "copper"}) {
    const ShockMaterial& m = shockMaterial(name);
    const MieGruneisen mg(m);
    const PolynomialEos poly(polynomialFromShock(m));
    auto err = [&](double mu) {
      const double rho = m.rho0 * (1.0 + mu);
      return std::abs(poly.pressure(rho, 0.0) - mg.pressure(rho, 0.0));
    };
    // Error O(mu^4): halving mu divides it by 16; [12, 20] allows the O(mu^5) term at mu = 0.02.
    const double ratio = err(0.02) / err(0.01);
    EXPECT_GT(ratio, 12.0) << name;
    EXPECT_LT(ratio, 20.0) << name;
    // The energy term is identical: (B0 + B1 mu) rho0 u = (gamma0 + a mu) rho0 u.
    const double rho = 1.1 * m.rho0;
    EXPECT_LT(rel(poly.pressure(rho, 1e6) - poly.pressure(rho, 0.0),
                  mg.pressure(rho, 1e6) - mg.pressure(rho, 0.0)), 1e-12) << name;
  }
}

TEST(PolynomialEos, ContinuousPressureAndReferenceSoundSpeed) {
  const ShockMaterial& m = shockMaterial("Al-2024");
  const PolynomialEos poly(polynomialFromShock(m));
  EXPECT_LT(rel(poly.soundSpeed(m.rho0, 0.0), m.c0), 1e-15);  // A1 = rho0 C0^2
  for (double u : {0.0, 1e5}) {
    const double dP = poly.pressure(m.rho0 * (1 + 1e-9), u) - poly.pressure(m.rho0 * (1 - 1e-9), u);
    EXPECT_LT(std::abs(dP), 1e-8 * m.rho0 * m.c0 * m.c0);  // slope A1 on both sides (T1 = A1)
  }
}

TEST(PolynomialEos, SpecificEnergyRoundTripAndBatch) {
  const PolynomialEos poly(polynomialFromShock(shockMaterial("copper")));
  std::vector<double> rho, u;
  for (int i = 0; i < 20; ++i) {
    rho.push_back(8930.0 * (0.8 + 0.03 * i));
    u.push_back(5e4 * i);
  }
  std::vector<double> P(rho.size()), cs(rho.size());
  std::vector<std::size_t> idx(rho.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = idx.size() - 1 - i;  // reversed order
  poly.evaluate(rho.data(), u.data(), P.data(), cs.data(), idx.data(), idx.size());
  for (std::size_t i = 0; i < rho.size(); ++i) {
    EXPECT_EQ(P[i], poly.pressure(rho[i], u[i]));
    EXPECT_EQ(cs[i], poly.soundSpeed(rho[i], u[i]));
    const double scale = std::max(u[i], std::abs(P[i]) / (8930.0 * 2.02));
    EXPECT_LT(std::abs(poly.specificEnergy(rho[i], P[i]) - u[i]), 1e-9 * scale);  // as above
  }
}

}  // namespace
}  // namespace ejecta
