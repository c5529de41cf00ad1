#pragma once
// Exact impedance match of a planar Chapman-Jouguet detonation arriving at an inert target: the
// Riemann problem at the explosive/target interface at the instant the front reaches it, with
// the products on the left at the C-J state (moving toward the target at u_CJ) and the target on
// the right at rest. A shock runs into the target along its principal Hugoniot; a wave runs back
// into the products from the C-J point:
//   - a softer target (water, p* < P_CJ): a centred rarefaction along the products' isentrope
//     through the C-J point, across which u + Phi(rho) keeps its C-J value, Phi = integral of
//     c/rho drho (Courant & Friedrichs, "Supersonic Flow and Shock Waves", 1948; Fickett & Davis,
//     "Detonation", 1979, sec. 2C);
//   - a stiffer target (copper, p* > P_CJ): a shock along the products' Hugoniot centred on the
//     C-J state, u = u_CJ - sqrt((p - P_CJ)(1/rho_CJ - 1/rho)),
//     e - e_CJ = (p + P_CJ)(1/rho_CJ - 1/rho) / 2.
// p* and u* are where the target's Hugoniot p_H(u) crosses that wave's p(u) curve (the impedance
// match of Forbes, "Shock Wave Compression of Condensed Matter", Springer 2012, ch. 3, and of
// Cooper, "Explosives Engineering", Wiley-VCH 1996). The target is taken from rest at zero
// pressure, as its Hugoniot fit is; ambient water at 0.1 MPa moves p* by ~1e-5 relative.
//
// Both branches are integrated or solved on the library's JWL and Mie-Grueneisen equations of
// state, so the result is what an exact solver of these two EOS gives, to ~1e-10 (RK4 in ln rho,
// bisection to round-off). docs/undex.md tabulates TNT into water: 14.5 GPa, 2.49 km/s.
#include <vector>

#include "sim/eos/jwl.hpp"
#include "sim/eos/mie_gruneisen.hpp"

namespace ejecta::exact {

// A state of the detonation products on the wave reflected from the interface.
struct ProductsState {
  double rho;  // [kg/m^3]
  double u;    // particle velocity, positive toward the target [m/s]
  double p;    // [Pa]
  double e;    // specific internal energy [J/kg]
};

// The state on the products' reflected wave (running back into them, away from the target)
// where the pressure is `pressure` (> 0): the isentrope below P_CJ, the Hugoniot above it.
// Throws std::invalid_argument for a pressure <= 0 or beyond the products' limiting compression.
ProductsState reflectedProductsState(const JwlParams& explosive, double pressure);

struct ImpedanceMatch {
  ProductsState products;  // products side of the interface after the reflection
  HugoniotState target;    // target side: shocked from rest (pressure, velocity, shock speed)
  bool reflectedShock;     // true: a shock runs back into the products (p* > P_CJ)
  double pressure() const { return target.P; }
  double velocity() const { return target.up; }
};

// The interface state when the C-J detonation of `explosive` reaches `target` at rest.
ImpedanceMatch detonationImpedanceMatch(const JwlParams& explosive, const ShockMaterial& target);

// A state of the self-similar solution.
struct InterfaceSample {
  double rho;     // [kg/m^3]
  double u;       // [m/s]
  double p;       // [Pa]
  bool products;  // true on the products' side of the contact
};

// The whole self-similar solution of that Riemann problem, x measured from the initial interface
// and t from the instant the C-J state meets the target: from left to right the C-J products, the
// reflected wave (fan or shock), the products at (p*, u*), the contact at u*, the shocked target
// and the target at rest. It is the exact solution of a detonation supported at the C-J state (a
// piston at u_CJ behind it); behind an unsupported one the Taylor wave weakens it at once.
class InterfaceRiemannSolution {
 public:
  InterfaceRiemannSolution(const JwlParams& explosive, const ShockMaterial& target);

  InterfaceSample sample(double xOverT) const;
  const ImpedanceMatch& match() const { return match_; }
  const ProductsState& chapmanJouguet() const { return cj_; }
  // Speeds of the reflected wave's edges: the head faces the C-J state, the tail the star state
  // (equal for a shock) [m/s].
  double reflectedHeadSpeed() const { return headSpeed_; }
  double reflectedTailSpeed() const { return tailSpeed_; }

 private:
  ImpedanceMatch match_{};
  ProductsState cj_{};
  double targetDensity_ = 0.0;
  double headSpeed_ = 0.0, tailSpeed_ = 0.0;
  std::vector<ProductsState> fan_;  // rarefaction from C-J to the star state
  std::vector<double> fanSpeed_;    // u - c of each fan state, increasing
};

}  // namespace ejecta::exact
