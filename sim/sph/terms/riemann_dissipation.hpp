#pragma once
// The star state of a pair's Riemann problem, for the Riemann-solver dissipation
// (SphOptions::dissipation = Riemann; docs/verification.md, "Riemann-solver dissipation").
//
// Godunov SPH (S. Inutsuka, J. Comput. Phys. 179, 238, 2002) replaces the pair's pressures and the
// artificial viscosity with the pressure P* of the one-dimensional Riemann problem between the two
// particles along their axis, and the energy equation's velocity with its star velocity u*.
//
// The solver (after Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics", 3rd ed.,
// 2009, ch. 4 and sec. 9.4) finds u* where the two sides' pressures meet: a side whose velocity
// drops by w > 0 towards the contact is shocked, P* - P_K = rho_K w W_K with the shock's speed
// relative to the gas ahead W_K = a w + sqrt((a w)^2 + c_K^2), a = (gamma + 1)/4 (the ideal gas's
// Rankine-Hugoniot relations solved for the shock speed; acoustic, W = c, for a weak shock and
// 2a w for a strong one); a side that the contact moves away from takes the acoustic
// rarefaction, P* - P_K = rho_K c_K w. For an ideal gas with gamma = 1.4 it is therefore exact
// when both waves are shocks and the linearised solver for weak waves. It needs of each side
// only its density, velocity, pressure and sound speed, so it applies to any equation of state:
// for a liquid or a solid 2a stands for the Hugoniot's U_s - u_p slope s (1.2-1.6 for metals and
// rock; S. P. Marsh, "LASL Shock Hugoniot Data", 1980), which the single a = 0.6 approximates.
// Equal pressures and velocities give P* = P and u* = u (a contact feels no dissipation).
#include <algorithm>
#include <cmath>

namespace ejecta {

// One side of the pair's Riemann problem: density [kg/m^3], velocity along the axis from left to
// right [m/s], pressure [Pa], sound speed [m/s].
struct RiemannSide {
  double rho, u, P, c;
};

struct StarState {
  double P;  // star pressure [Pa]
  double u;  // star (contact) velocity along the axis [m/s]
};

// a = (gamma + 1)/4 of the shock speed above, for gamma = 1.4 (air; the strong-shock limit of
// U_s - u_p is 2a = 1.2).
inline constexpr double kShockSlope = 0.6;
// Newton steps at most: a bound, which the tests' strong shocks stay well within.
inline constexpr int kMaxNewtonSteps = 12;

// Through a side's wave as its velocity drops by w towards the contact: the pressure change
// rho w W(w), W the shock's speed for w > 0 and c for a rarefaction; and its derivative in w (for
// Newton's steps only).
inline double pressureChange(const RiemannSide& K, double w) {
  if (w <= 0.0) return K.rho * K.c * w;
  const double aw = kShockSlope * w;
  return K.rho * w * (aw + std::sqrt(aw * aw + K.c * K.c));
}
inline double pressureSlope(const RiemannSide& K, double w) {
  if (w <= 0.0) return K.rho * K.c;
  const double aw = kShockSlope * w, root = std::sqrt(aw * aw + K.c * K.c);
  return K.rho * (2.0 * aw + root + aw * aw / root);
}

inline StarState twoShockStar(const RiemannSide& L, const RiemannSide& R) {
  const double ZL = L.rho * L.c, ZR = R.rho * R.c;  // acoustic impedances
  // Both sides without sound speed or density (no wave can separate them): their mean.
  if (!(ZL + ZR > 0.0)) return {0.5 * (L.P + R.P), 0.5 * (L.u + R.u)};
  // u* where both sides reach one pressure, P_L + dP_L(u_L - u*) = P_R + dP_R(u* - u_R): Newton's
  // method from the acoustic solution. The difference falls monotonically in u* and is convex on
  // either side of its kink, as the exact solver's pressure function is (Toro sec. 4.3.1), so
  // the iteration converges from the acoustic start (Toro test 5's pair of shocks: a few steps to
  // 1e-12).
  double u = (ZL * L.u + ZR * R.u + L.P - R.P) / (ZL + ZR);
  // Pressures agree when they differ by round-off of the terms that make them.
  const double tolerance =
      1e-12 * (std::abs(L.P) + std::abs(R.P) +
               (ZL + ZR) * (std::abs(L.u) + std::abs(R.u) + L.c + R.c));
  double dPL = pressureChange(L, L.u - u), dPR = pressureChange(R, u - R.u);
  // Two rarefactions (most pairs of an expanding flow) are acoustic already: no step.
  for (int step = 0; step < kMaxNewtonSteps; ++step) {
    const double mismatch = L.P + dPL - R.P - dPR;
    if (!(std::abs(mismatch) > tolerance)) break;
    u += mismatch / (pressureSlope(L, L.u - u) + pressureSlope(R, u - R.u));
    dPL = pressureChange(L, L.u - u);
    dPR = pressureChange(R, u - R.u);
  }
  // The two sides' pressures agree to the tolerance: their mean, the same from either side.
  double P = 0.5 * (L.P + dPL + R.P + dPR);
  // The acoustic rarefaction can overshoot below vacuum: no tension where neither side has any.
  P = std::max(P, std::min({L.P, R.P, 0.0}));
  return {P, u};
}

}  // namespace ejecta
