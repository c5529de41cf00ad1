// JWL detonation products: the C-J state implied by (rho0, D, P_CJ, E0), the ideal-gas limit of
// large expansion, exact energy inverse, batched = single point, c^2 > 0.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/eos/jwl.hpp"

namespace ejecta {
namespace {

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// The C-J point lies on the Rayleigh line (rho_CJ, u_p from D and P_CJ) with the products'
// Hugoniot energy e0 + P_CJ (v0 - v_CJ)/2. A JWL fit to the cylinder test passes through it, so
// the JWL pressure there reproduces the published P_CJ. The brief allowed 5%; the sets agree to
// 2e-4, so 1e-3 (rounding of the 3-4 printed digits) also catches a mistyped third digit.
TEST(Jwl, ChapmanJouguetPressureFromRayleighLineAndEnergy) {
  for (const auto& name : jwlExplosiveNames()) {
    const JwlParams& p = jwlExplosive(name);
    const Jwl eos(p);
    const ChapmanJouguetState cj = chapmanJouguetState(p);
    const double P = eos.pressure(cj.rho, cj.u);
    EXPECT_LT(rel(P, p.pCJ), 1e-3) << name << ": P_JWL(C-J) = " << P << " vs " << p.pCJ;
    RecordProperty(name + "_PCJ_rel_error", std::to_string(rel(P, p.pCJ)));
  }
}

// At the C-J point the flow behind the front is sonic: D = u_p + c (the JWL isentrope is tangent
// to the Rayleigh line). Observed 1.4e-4; 1e-3 as above (c is one derivative of the same fit).
TEST(Jwl, ChapmanJouguetStateIsSonic) {
  for (const auto& name : jwlExplosiveNames()) {
    const JwlParams& p = jwlExplosive(name);
    const Jwl eos(p);
    const ChapmanJouguetState cj = chapmanJouguetState(p);
    const double c = eos.soundSpeed(cj.rho, cj.u);
    EXPECT_LT(rel(cj.up + c, p.dCJ), 1e-3) << name << ": u + c = " << cj.up + c;
    RecordProperty(name + "_DCJ_rel_error", std::to_string(rel(cj.up + c, p.dCJ)));
  }
}

TEST(Jwl, LargeExpansionIsIdealGasWithGammaOnePlusOmega) {
  const JwlParams& p = jwlExplosive("TNT");
  const Jwl eos(p);
  const double u = 2e6;
  for (double V : {50.0, 200.0, 1e4}) {
    const double rho = p.rho0 / V;
    // exp(-R2 V) <= exp(-47): the exponential terms are below 1e-12 of w rho u.
    EXPECT_LT(rel(eos.pressure(rho, u), p.omega * rho * u), 1e-12) << V;
    EXPECT_LT(rel(eos.soundSpeedSquared(rho, u), p.omega * (1.0 + p.omega) * u), 1e-12) << V;
  }
}

TEST(Jwl, SpecificEnergyRoundTrip) {
  for (const auto& name : jwlExplosiveNames()) {
    const JwlParams& p = jwlExplosive(name);
    const Jwl eos(p);
    for (double V : {0.4, 0.7, 1.0, 2.0, 7.0, 50.0})
      for (double u : {0.0, 1e5, 4e6, 1e7}) {
        const double rho = p.rho0 / V;
        const double P = eos.pressure(rho, u);
        // The subtraction P - P(rho, 0) loses log10(|P|/(w rho u)) digits; scale accordingly.
        const double scale = std::max(u, std::abs(P) / (p.omega * rho));
        EXPECT_LT(std::abs(eos.specificEnergy(rho, P) - u), 1e-12 * scale)
            << name << " V " << V << " u " << u;
      }
    EXPECT_THROW(eos.specificEnergy(0.0, 1e9), std::domain_error);
  }
}

TEST(Jwl, BatchedEqualsSinglePoint) {
  const Jwl eos(jwlExplosive("TNT"));
  std::vector<double> rho, u;
  for (int i = 0; i < 30; ++i) {
    rho.push_back(1630.0 / (0.5 + 0.4 * i));
    u.push_back(2e5 * i);
  }
  std::vector<double> P(rho.size(), -1.0), cs(rho.size(), -1.0);
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < rho.size(); i += 2) idx.push_back(i);
  eos.evaluate(rho.data(), u.data(), P.data(), cs.data(), idx.data(), idx.size());
  for (std::size_t i = 0; i < rho.size(); ++i) {
    if (i % 2 == 0) {
      EXPECT_EQ(P[i], eos.pressure(rho[i], u[i]));  // same code path: bitwise equal
      EXPECT_EQ(cs[i], eos.soundSpeed(rho[i], u[i]));
    } else {
      EXPECT_EQ(P[i], -1.0);
      EXPECT_EQ(cs[i], -1.0);
    }
  }
}

TEST(Jwl, SoundSpeedSquaredPositiveOnDenseGrid) {
  for (const auto& name : jwlExplosiveNames()) {
    const JwlParams& p = jwlExplosive(name);
    const Jwl eos(p);
    // Products from 2.5x compression (beyond any C-J state, V_CJ ~ 0.73) to 1e4x expansion,
    // with u up to twice the C-J energy. u = 0 only to V = 10: beyond, every term underflows
    // and c^2 -> w (1 + w) u = 0 is the correct cold, fully expanded limit (floored in use).
    for (int i = 0; i <= 400; ++i) {
      const double V = 0.4 * std::pow(2.5e4, i / 400.0);
      for (int j = (V <= 10.0 ? 0 : 1); j <= 40; ++j) {
        const double u = 2e7 * j / 40.0;
        EXPECT_GT(eos.soundSpeedSquared(p.rho0 / V, u), 0.0) << name << " V " << V << " u " << u;
      }
    }
    for (double rho : {0.0, 1e-300, 1e-3, 1e5})
      for (double u : {-1e7, 0.0, 1e8}) {
        const double c = eos.soundSpeed(rho, u);
        EXPECT_TRUE(std::isfinite(c) && c > 0.0) << name << " rho " << rho << " u " << u;
        EXPECT_TRUE(std::isfinite(eos.pressure(rho, u))) << name << " rho " << rho;
      }
  }
}

TEST(Jwl, LibraryLookupListsNamesAndEnergyConvention) {
  const JwlParams& tnt = jwlExplosive("TNT");
  EXPECT_DOUBLE_EQ(tnt.specificDetonationEnergy(), 7.0e9 / 1630.0);  // E0 is per unit volume
  try {
    jwlExplosive("ANFO-9000");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    for (const auto& n : jwlExplosiveNames()) EXPECT_NE(msg.find(n), std::string::npos) << n;
  }
  JwlParams bad = tnt;
  bad.omega = 0.0;
  EXPECT_THROW(Jwl{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace ejecta
