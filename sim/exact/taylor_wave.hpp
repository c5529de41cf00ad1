#pragma once
// Exact solution of a planar Chapman-Jouguet detonation running from a rigid wall (or, by
// symmetry, from the middle of a bar lit at its centre) into explosive at rest: the steady C-J
// front at x = D t followed by the Taylor (1950) rarefaction, a centred simple wave in which the
// C- Riemann invariant u - Phi(rho), Phi = integral of c/rho drho along the products' isentrope
// through the C-J point, keeps its C-J value, and x/t = u + c; behind it the products rest at the
// wall state (u = 0) for x < c_wall t. G. I. Taylor, Proc. R. Soc. Lond. A 200 (1950) 235-247;
// Fickett & Davis, "Detonation", 1979, sec. 2C.
//
// The isentrope is integrated numerically (de/drho = P/rho^2, RK4 in log rho) on the JWL
// products' EOS, so the solution is exact up to a quadrature error far below any SPH error.
#include <vector>

#include "sim/eos/jwl.hpp"

namespace ejecta::exact {

struct DetonationState {
  double rho;  // [kg/m^3]
  double u;    // particle velocity away from the wall [m/s]
  double p;    // [Pa]
  double e;    // specific internal energy [J/kg]
};

class TaylorWave {
 public:
  explicit TaylorWave(const JwlParams& explosive);

  // State at x/t >= 0 (x from the wall). Ahead of the front (x/t > D): the explosive at rest,
  // rho0, u = 0, p = 0, e = e0.
  DetonationState sample(double xOverT) const;

  const DetonationState& chapmanJouguet() const { return cj_; }
  const DetonationState& wall() const { return table_.back().state; }
  double wallSoundSpeed() const { return table_.back().c; }
  double detonationVelocity() const { return D_; }

 private:
  struct Node {
    DetonationState state;
    double c;  // sound speed [m/s]
  };
  std::vector<Node> table_;  // along the isentrope from the C-J point to the wall state
  DetonationState cj_{};
  DetonationState ahead_{};
  double D_ = 0.0;
};

}  // namespace ejecta::exact
