#pragma once
// The star state of a pair's Riemann problem, for the Riemann-solver dissipation
// (SphOptions::dissipation = Riemann; docs/verification.md, "Riemann-solver dissipation").
//
// Godunov SPH (S. Inutsuka, J. Comput. Phys. 179, 238, 2002) replaces the pair's pressures and the
// artificial viscosity with the pressure P* of the one-dimensional Riemann problem between the two
// particles along their axis, and the energy equation's velocity with its star velocity u*.
//
// The solver (after Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics", 3rd ed.,
// 2009: ch. 4's pressure functions, ch. 9's two-shock approximation) finds u* where the two sides' pressures meet: a side whose velocity
// drops by w > 0 towards the contact is shocked, P* - P_K = rho_K w W_K with the shock's speed
// relative to the gas ahead W_K = a w + sqrt((a w)^2 + c_K^2), a = (gamma + 1)/4 (the ideal gas's
// Rankine-Hugoniot relations solved for the shock speed; acoustic, W = c, for a weak shock and
// 2a w for a strong one); a side that the contact moves away from takes the acoustic
// rarefaction, P* - P_K = rho_K c_K w. For an ideal gas with gamma = 1.4 it is therefore exact
// when both waves are shocks and the linearised solver for weak waves. It needs of each side
// only its density, velocity, pressure and sound speed, so it can be applied to any equation of
// state, with two approximations there: a liquid's or a solid's shock speed is U_s = c + s w
// (s = 1.2-1.9; S. P. Marsh, "LASL Shock Hugoniot Data", 1980), which this W meets only in the
// strong limit (2a = 1.2) and undershoots by (s - a) w for weak shocks; and a strong rarefaction
// (a detonation's products beside air) is far from acoustic (its u* several times too small).
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
// Steps at most: a bound, which the tests' strong shocks stay well within.
inline constexpr int kMaxSolverSteps = 12;

// Through a side's wave as its velocity drops by w towards the contact: the pressure change
// rho w W(w), W the shock's speed for w > 0 and c for a rarefaction.
inline double pressureChange(const RiemannSide& K, double w) {
  if (w <= 0.0) return K.rho * K.c * w;
  const double aw = kShockSlope * w;
  return K.rho * w * (aw + std::sqrt(aw * aw + K.c * K.c));
}

// The change and its first and second derivatives in w from one square root (the solver's inner
// loop, where the roots are most of the cost).
struct PressureChange {
  double change, slope, curvature;
};
inline PressureChange pressureChangeAndSlope(const RiemannSide& K, double w) {
  if (w <= 0.0) return {K.rho * K.c * w, K.rho * K.c, 0.0};
  const double aw = kShockSlope * w, root = std::sqrt(aw * aw + K.c * K.c);
  const double q = root > 0.0 ? aw / root : 1.0;  // 1: the strong limit (a cold gas, aw^2 -> 0)
  return {K.rho * w * (aw + root), K.rho * (2.0 * aw + root + aw * q),
          K.rho * kShockSlope * (2.0 + 3.0 * q - q * q * q)};
}

inline StarState twoShockStar(const RiemannSide& L, const RiemannSide& R) {
  const double ZL = L.rho * L.c, ZR = R.rho * R.c;  // acoustic impedances
  const bool approaching = L.u > R.u;
  // The start: the acoustic solution, or where the two sides approach faster than sound (or have
  // none: a cold gas) the strong shocks' own, rho_L (u_L - u)^2 = rho_R (u - u_R)^2.
  double u;
  if (approaching && L.u - R.u > L.c + R.c) {
    const double sL = std::sqrt(L.rho), sR = std::sqrt(R.rho);
    if (!(sL + sR > 0.0)) return {0.5 * (L.P + R.P), 0.5 * (L.u + R.u)};
    u = (sL * L.u + sR * R.u) / (sL + sR);
  } else {
    // Neither sound nor a collision (two cold gases parting): no wave joins them.
    if (!(ZL + ZR > 0.0)) return {0.5 * (L.P + R.P), 0.5 * (L.u + R.u)};
    u = (ZL * L.u + ZR * R.u + L.P - R.P) / (ZL + ZR);
  }
  // u* where both sides reach one pressure, P_L + dP_L(u_L - u*) = P_R + dP_R(u* - u_R). The
  // difference falls monotonically in u*, with kinks where either side turns from rarefaction to
  // shock, convex below an inflection and concave above it, as the exact solver's pressure
  // function (Toro sec. 4.3). Solved by Halley's steps (Newton's with the curvature: cubic
  // convergence), with Newton's where the curvature would more than double the step: on the 3D
  // Sedov blast (n = 30) no pair takes more than three, Newton alone up to five. Converged when
  // the two pressures differ by round-off of the terms that make them. A step from a mismatch
  // below 1e-7 of them is the last: the pressures are carried to its end along their slopes (what
  // the curvature adds, and what is left even at a kink, where the convergence is quadratic, is
  // ~1e-14 of the terms), which saves the roots of one more evaluation.
  PressureChange left = pressureChangeAndSlope(L, L.u - u);
  PressureChange right = pressureChangeAndSlope(R, u - R.u);
  for (int step = 0; step < kMaxSolverSteps; ++step) {
    const double mismatch = L.P + left.change - R.P - right.change;
    const double scale =
        std::abs(L.P) + std::abs(R.P) + std::abs(left.change) + std::abs(right.change);
    if (!(std::abs(mismatch) > 1e-12 * scale)) break;
    const double slope = left.slope + right.slope;
    if (!(slope > 0.0)) break;  // both sides without sound and without a shock: no better u
    const double halley = 2.0 * slope * slope - mismatch * (left.curvature - right.curvature);
    const double delta =
        halley > slope * slope ? 2.0 * mismatch * slope / halley : mismatch / slope;
    u += delta;
    if (std::abs(mismatch) <= 1e-7 * scale) {
      left.change -= left.slope * delta;
      right.change += right.slope * delta;
      break;
    }
    left = pressureChangeAndSlope(L, L.u - u);
    right = pressureChangeAndSlope(R, u - R.u);
  }
  // The two sides' pressures agree to round-off: their mean, the same from either side.
  double P = 0.5 * (L.P + left.change + R.P + right.change);
  // Acoustic rarefactions pulled apart faster than sound would give a gas tension: none where
  // neither side has any. (The force pass never reaches it: a receding pair has no jump there.)
  P = std::max(P, std::min({L.P, R.P, 0.0}));
  return {P, u};
}

}  // namespace ejecta
