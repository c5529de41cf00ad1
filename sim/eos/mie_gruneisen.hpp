#pragma once
// Shock (Mie-Grueneisen) equation of state with a Hugoniot reference curve, and the polynomial
// form of the same law. Equations, conventions and library sources: docs/eos_shock_jwl.md.
//
// Energy convention: ejecta's u is specific internal energy [J/kg]. The published forms (Steinberg,
// LS-DYNA *EOS_GRUNEISEN, AUTODYN) write the energy term with E = energy per unit INITIAL volume
// [J/m^3], so E = rho0 * u everywhere below.
#include <string>
#include <string_view>
#include <vector>

#include "sim/eos/state_eos.hpp"

namespace ejecta {

// Hugoniot fit Us = C0 + S1 up + S2 up^2/Us + S3 up^3/Us^2 (S2 = S3 = 0: the linear fit
// Us = C0 + s up), Grueneisen gamma0 and first-order volume correction a (Steinberg's b), with
// rho*Gamma = rho0 (gamma0 + a mu).
struct ShockMaterial {
  std::string name;
  double rho0 = 0.0;    // reference density [kg/m^3]
  double c0 = 0.0;      // bulk sound speed, intercept of the Us-up fit [m/s]
  double s1 = 0.0;      // linear slope
  double s2 = 0.0;      // quadratic coefficient (of up^2/Us)
  double s3 = 0.0;      // cubic coefficient (of up^3/Us^2)
  double gamma0 = 0.0;  // Grueneisen coefficient at rho0
  double a = 0.0;       // first-order volume correction to gamma0
  std::string source;   // where the numbers come from, and what was verified
};

// Library lookup by name; throws std::invalid_argument listing the known names.
const ShockMaterial& shockMaterial(std::string_view name);
std::vector<std::string> shockMaterialNames();

// A state on the principal Hugoniot from (rho0, P = 0, u = 0) at particle velocity up.
struct HugoniotState {
  double us = 0.0;   // shock velocity [m/s]
  double up = 0.0;   // particle velocity [m/s]
  double rho = 0.0;  // rho0 Us / (Us - up)
  double P = 0.0;    // rho0 Us up
  double u = 0.0;    // up^2 / 2 (specific)
};
// Us from up, solving the implicit cubic fit by Newton iteration (exact for the linear fit).
double hugoniotShockVelocity(const ShockMaterial& m, double up);
HugoniotState hugoniotState(const ShockMaterial& m, double up);

// Compression (mu = rho/rho0 - 1 > 0):
//   P = rho0 C0^2 mu [1 + (1 - gamma0/2) mu - (a/2) mu^2]
//       / [1 - (S1-1) mu - S2 mu^2/(mu+1) - S3 mu^3/(mu+1)^2]^2 + (gamma0 + a mu) rho0 u
// Expansion (mu <= 0):  P = rho0 C0^2 mu + (gamma0 + a mu) rho0 u.
class MieGruneisen final : public StateEquationOfState<MieGruneisen> {
 public:
  explicit MieGruneisen(ShockMaterial material);
  std::string name() const override { return "mie_gruneisen:" + m_.name; }
  // Exact inverse (P is linear in u). Returns a negative u where (rho, P) lies below the u = 0
  // curve; throws std::domain_error for rho <= 0 or where dP/du vanishes.
  double specificEnergy(double rho, double P) const override;
  double referenceDensity() const override { return m_.rho0; }

  // Compression beyond which mu is clamped: 99% of the first zero of the denominator (the fit's
  // limiting compression), or +infinity when the denominator has no zero.
  double maxCompression() const { return muMax_; }
  const ShockMaterial& material() const { return m_; }

 private:
  friend class StateEquationOfState<MieGruneisen>;
  double soundSpeedFloor() const { return csFloor_; }
  struct State {
    double P;
    double c2;
  };
  State state(double rho, double u) const;

  ShockMaterial m_;
  double muMax_;
  double csFloor_;
};

// AUTODYN polynomial EOS. Compression (mu > 0):
//   P = A1 mu + A2 mu^2 + A3 mu^3 + (B0 + B1 mu) rho0 u
// Expansion (mu <= 0): P = T1 mu + T2 mu^2 + B0 rho0 u.
struct PolynomialEosParams {
  std::string name;
  double rho0 = 0.0;  // [kg/m^3]
  double a1 = 0.0, a2 = 0.0, a3 = 0.0;  // [Pa]
  double b0 = 0.0, b1 = 0.0;            // dimensionless
  double t1 = 0.0, t2 = 0.0;            // [Pa]; T1 = 0 means T1 = A1 (AUTODYN's convention)
  std::string source;
};

// Third-order Taylor expansion in mu of MieGruneisen(m) at u = 0, with B0 = gamma0, B1 = a,
// T1 = A1, T2 = 0, so both laws agree to O(mu^4) in compression (docs/eos_shock_jwl.md).
PolynomialEosParams polynomialFromShock(const ShockMaterial& m);

class PolynomialEos final : public StateEquationOfState<PolynomialEos> {
 public:
  explicit PolynomialEos(PolynomialEosParams params);
  std::string name() const override { return "polynomial:" + p_.name; }
  double specificEnergy(double rho, double P) const override;
  const PolynomialEosParams& params() const { return p_; }

 private:
  friend class StateEquationOfState<PolynomialEos>;
  double soundSpeedFloor() const { return csFloor_; }
  struct State {
    double P;
    double c2;
  };
  State state(double rho, double u) const;

  PolynomialEosParams p_;
  double csFloor_;
};

}  // namespace ejecta
