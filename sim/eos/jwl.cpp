#include "sim/eos/jwl.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/join.hpp"

namespace ejecta {

namespace {

// Sound-speed floor as a fraction of sqrt(A/rho0) (about 15 km/s for TNT): keeps c real and
// positive for SPH's time step in states no detonation reaches (see the dense-grid test).
constexpr double kSoundFloorFraction = 1e-3;

// The library. Dobratz & Crawford (1985), LLNL Explosives Handbook, UCRL-52997 Change 2,
// Table 8-3 (JWL parameters) as reproduced in the LS-DYNA/Radioss example decks; docs/
// eos_shock_jwl.md records what was verified and the C-J consistency check that tests them.
const std::vector<JwlParams>& library() {
  static const std::vector<JwlParams> lib = {
      {"TNT", 1630.0, 3.712e11, 3.231e9, 4.15, 0.95, 0.30, 7.0e9, 6930.0, 21.0e9,
       "Dobratz & Crawford (1985) UCRL-52997, TNT: A 3.712 Mbar, B 0.03231 Mbar, R1 4.15, "
       "R2 0.95, w 0.30, E0 0.070 Mbar, D 0.693 cm/us, P_CJ 0.21 Mbar, rho0 1.630 g/cc; the same "
       "numbers appear in the Altair Radioss /MAT/JWL TNT example (LS-DYNA example 46)"},
      // The set the seed's Table 3.3 garbles ("B1", "R2 4.15", "w 0.9" are shifted rows).
      {"TNT-AUTODYN", 1630.0, 3.7377e11, 3.7471e9, 4.15, 0.90, 0.35, 6.0e9, 6930.0, 21.0e9,
       "ANSYS AUTODYN material library TNT, as printed (shifted) in seed Table 3.3: A 373.77 "
       "GPa, B 3.7471 GPa, R1 4.15, R2 0.90, w 0.35, E0 6.0 GJ/m^3, D 6930 m/s, P_CJ 21 GPa, "
       "rho0 1630 kg/m^3; AUTODYN cites Dobratz (1981) UCRL-52997; not verified against it"},
      {"CompB", 1717.0, 5.242e11, 7.678e9, 4.20, 1.10, 0.34, 8.5e9, 7980.0, 29.5e9,
       "Dobratz & Crawford (1985) UCRL-52997, Composition B Grade A; recalled values, checked "
       "only through the C-J consistency test (tests/sim/eos/test_jwl.cpp)"},
      {"C-4", 1601.0, 6.0977e11, 1.295e10, 4.50, 1.40, 0.25, 9.0e9, 8193.0, 28.0e9,
       "Dobratz & Crawford (1985) UCRL-52997, C-4; recalled values, checked only through the "
       "C-J consistency test (tests/sim/eos/test_jwl.cpp)"},
  };
  return lib;
}

void requirePositive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("JWL: ") + what + " must be positive and finite");
}

}  // namespace

const JwlParams& jwlExplosive(std::string_view name) {
  for (const auto& p : library())
    if (p.name == name) return p;
  throw std::invalid_argument("unknown JWL explosive '" + std::string(name) + "'; known: " +
                              joinList(library(), &JwlParams::name));
}

std::vector<std::string> jwlExplosiveNames() {
  std::vector<std::string> names;
  for (const auto& p : library()) names.push_back(p.name);
  return names;
}

ChapmanJouguetState chapmanJouguetState(const JwlParams& p) {
  ChapmanJouguetState s;
  s.up = p.pCJ / (p.rho0 * p.dCJ);                // momentum: P = rho0 D up
  s.rho = p.rho0 * p.dCJ / (p.dCJ - s.up);        // mass: rho (D - up) = rho0 D
  s.u = p.specificDetonationEnergy() + 0.5 * p.pCJ * (1.0 / p.rho0 - 1.0 / s.rho);  // energy
  return s;
}

Jwl::Jwl(JwlParams params) : p_(std::move(params)), csFloor_(0.0) {
  requirePositive(p_.rho0, "rho0");
  requirePositive(p_.A, "A");
  requirePositive(p_.R1, "R1");
  requirePositive(p_.R2, "R2");
  requirePositive(p_.omega, "omega");
  if (!std::isfinite(p_.B)) throw std::invalid_argument("JWL: B must be finite");
  csFloor_ = kSoundFloorFraction * std::sqrt(p_.A / p_.rho0);
}

Jwl::State Jwl::state(double rho, double u) const {
  // rho -> 0 is the free-expansion limit; keep V finite so exp(-R V) underflows to 0 cleanly.
  const double r = std::max(rho, 1e-12 * p_.rho0);
  const double V = p_.rho0 / r;
  const double w = p_.omega;
  double P = w * r * u;
  double dPdrho = w * u;
  // Each exponential term T = K (1 - w/(R V)) e^{-R V} has
  // dT/drho = (K e^{-R V} / rho) (R V - w - w/(R V)).
  const double K[2] = {p_.A, p_.B};
  const double R[2] = {p_.R1, p_.R2};
  for (int i = 0; i < 2; ++i) {
    const double rv = R[i] * V;
    const double ke = K[i] * std::exp(-rv);
    P += ke * (1.0 - w / rv);
    dPdrho += ke / r * (rv - w - w / rv);
  }
  // c^2 = dP/drho|_u + (P/rho^2) dP/du|_rho with dP/du = w rho.
  return {P, dPdrho + w * P / r};
}

double Jwl::specificEnergy(double rho, double P) const {
  if (!(rho > 0.0)) throw std::domain_error("JWL: density must be positive");
  const double r = std::max(rho, 1e-12 * p_.rho0);
  return (P - state(rho, 0.0).P) / (p_.omega * r);
}

}  // namespace ejecta
