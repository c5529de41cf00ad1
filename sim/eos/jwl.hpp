#pragma once
// Jones-Wilkins-Lee equation of state for detonation products. Equations, conventions and
// library sources: docs/eos_shock_jwl.md.
//
// Standard form, with V = rho0/rho and E = energy per unit INITIAL volume [J/m^3]:
//   P = A (1 - w/(R1 V)) exp(-R1 V) + B (1 - w/(R2 V)) exp(-R2 V) + w E / V.
// ejecta carries specific energy u [J/kg]: E = rho0 u, so w E / V = w rho u.
#include <string>
#include <string_view>
#include <vector>

#include "sim/eos/state_eos.hpp"

namespace ejecta {

struct JwlParams {
  std::string name;
  double rho0 = 0.0;   // unreacted explosive density [kg/m^3]
  double A = 0.0;      // [Pa]
  double B = 0.0;      // [Pa]
  double R1 = 0.0;     // dimensionless
  double R2 = 0.0;     // dimensionless
  double omega = 0.0;  // Grueneisen coefficient of the products
  double E0 = 0.0;     // detonation energy per unit initial volume [J/m^3]; e0 = E0/rho0 [J/kg]
  double dCJ = 0.0;    // Chapman-Jouguet detonation velocity [m/s]
  double pCJ = 0.0;    // Chapman-Jouguet pressure [Pa]
  std::string source;

  double specificDetonationEnergy() const { return E0 / rho0; }  // e0 [J/kg]
};

// Library lookup by name; throws std::invalid_argument listing the known names.
const JwlParams& jwlExplosive(std::string_view name);
std::vector<std::string> jwlExplosiveNames();

// The C-J state implied by (rho0, D, P_CJ) through the Rayleigh line and the products'
// Hugoniot energy: u_p = P/(rho0 D), rho = rho0 D/(D - u_p), u = e0 + P (1/rho0 - 1/rho)/2.
struct ChapmanJouguetState {
  double rho = 0.0;  // [kg/m^3]
  double up = 0.0;   // particle velocity [m/s]
  double u = 0.0;    // specific internal energy [J/kg]
};
ChapmanJouguetState chapmanJouguetState(const JwlParams& p);

class Jwl final : public StateEquationOfState<Jwl> {
 public:
  explicit Jwl(JwlParams params);
  std::string name() const override { return "jwl:" + p_.name; }
  // Exact inverse, u = (P - P_A - P_B) / (w rho). Throws std::domain_error for rho <= 0.
  double specificEnergy(double rho, double P) const override;

  const JwlParams& params() const { return p_; }

 private:
  friend class StateEquationOfState<Jwl>;
  double soundSpeedFloor() const { return csFloor_; }
  struct State {
    double P;
    double c2;
  };
  State state(double rho, double u) const;

  JwlParams p_;
  double csFloor_;
};

}  // namespace ejecta
