#pragma once
// Limited linear reconstruction of velocities for the artificial viscosity (docs/undex.md,
// "Reconstructed viscosity").
//
// The Monaghan viscosity acts on the velocity jump between two particles. In a smooth flow that
// jump is the velocity gradient times the spacing, so a constant-alpha viscosity damps every
// compression, and it widens a weak shock to a width of about alpha c h / du (many h when
// du << c). Reconstructing both velocities to the pair's midpoint from each particle's gradient
// removes the linear part of the jump: a linear field feels no viscosity at all, and what
// remains is the jump the gradients cannot explain, a shock. Van Leer's limiter (B. van Leer,
// J. Comput. Phys. 14, 361, 1974; the symmetric form 4 r / (1 + r)^2 of the two one-sided slopes'
// ratio r) turns the reconstruction off where the two slopes disagree, at a shock front or an
// extremum, so there the viscosity is the full first-order one. The same construction is used in
// SPH by N. Frontiere, C. D. Raskin & J. M. Owen (J. Comput. Phys. 332, 160, 2017, CRKSPH) and
// S. Rosswog (MNRAS 498, 4230, 2020, MAGMA2).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "sim/hydro_workspace.hpp"
#include "sim/particles.hpp"

namespace ejecta {

// Velocity gradient G (G[a][b] = dv_a/dx_b) that is exact for a linear velocity field:
// with A = sum_j f_j dv_ij (x) dx_ij and M = sum_j f_j dx_ij (x) dx_ij over any pair weights f_j,
// a linear field has dv_ij = G dx_ij, so A = G M and G = A M^-1 (the linear correction of
// G. R. Johnson & S. R. Beissel, IJNME 39, 2725, 1996; J. Bonet & T.-S. L. Lok, CMAME 180, 97,
// 1999). Returns false and leaves G zero when M is too close to singular to invert (a particle
// with its neighbours on a line or a plane: a free edge), where the plain viscosity is the safe
// choice.
template <int D>
bool correctedGradient(const double A[3][3], const double M[3][3], double G[3][3]) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) G[a][b] = 0.0;
  double inv[3][3] = {};
  double det, scale;
  if constexpr (D == 1) {
    det = M[0][0];
    scale = std::abs(M[0][0]);
    inv[0][0] = 1.0;
  } else if constexpr (D == 2) {
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    scale = 0.5 * std::abs(M[0][0] + M[1][1]);
    scale *= scale;
    inv[0][0] = M[1][1];
    inv[0][1] = -M[0][1];
    inv[1][0] = -M[1][0];
    inv[1][1] = M[0][0];
  } else {
    inv[0][0] = M[1][1] * M[2][2] - M[1][2] * M[2][1];
    inv[0][1] = M[0][2] * M[2][1] - M[0][1] * M[2][2];
    inv[0][2] = M[0][1] * M[1][2] - M[0][2] * M[1][1];
    inv[1][0] = M[1][2] * M[2][0] - M[1][0] * M[2][2];
    inv[1][1] = M[0][0] * M[2][2] - M[0][2] * M[2][0];
    inv[1][2] = M[0][2] * M[1][0] - M[0][0] * M[1][2];
    inv[2][0] = M[1][0] * M[2][1] - M[1][1] * M[2][0];
    inv[2][1] = M[0][1] * M[2][0] - M[0][0] * M[2][1];
    inv[2][2] = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    det = M[0][0] * inv[0][0] + M[0][1] * inv[1][0] + M[0][2] * inv[2][0];
    scale = std::abs(M[0][0] + M[1][1] + M[2][2]) / 3.0;
    scale = scale * scale * scale;
  }
  // For a full, isotropic neighbourhood det = scale; along a free edge det/scale falls toward 0.
  // 1e-3 keeps every interior and most surface particles and refuses near-degenerate ones.
  if (!(std::abs(det) > 1e-3 * scale)) return false;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      double sum = 0.0;
      for (int c = 0; c < D; ++c) sum += A[a][c] * inv[c][b];
      G[a][b] = sum / det;
    }
  return true;
}

// Barth & Jespersen's limiter on each particle's gradient (T. J. Barth & D. C. Jespersen,
// AIAA 89-0366, 1989): each row of G is scaled so that the velocity reconstructed to the midpoint
// of every pair stays within the range of the velocities the particle sees. Real particles only;
// ghosts take their source's limited gradient afterwards.
void limitVelocityGradients(const ParticleSet& p, HydroWorkspace& ws);

// Van Leer's limiter as a function of the ratio of the two one-sided slopes: 1 when they agree,
// falling to 0 as they differ by a large factor in either direction, 0 when they differ in sign.
// Symmetric under r -> 1/r, so a pair's limiter does not depend on which particle is i.
inline double vanLeerLimiter(double ratio) {
  if (!(ratio > 0.0)) return 0.0;  // opposite signs, zero or NaN: no reconstruction
  const double denom = 1.0 + ratio;
  return std::min(1.0, 4.0 * ratio / (denom * denom));
}

// The pair's velocity difference after reconstruction to the midpoint, projected on dx:
//   (v_i* - v_j*) . dx = [dv - phi (G_i + G_j) dx / 2] . dx,   dx = x_i - x_j, dv = v_i - v_j,
// phi the van Leer limiter of the ratio of the two slopes dx . G dx. Negative: the reconstructed
// velocities approach. G holds every particle's gradient at component 3 a + b.
template <int D>
double reconstructedApproach(const double dx[3], const double dv[3],
                             const std::array<std::vector<double>, 9>& G, std::size_t i,
                             std::size_t j) {
  double slopeI = 0.0, slopeJ = 0.0, approach = 0.0;
  for (int a = 0; a < D; ++a) {
    double deltaI = 0.0, deltaJ = 0.0;
    for (int b = 0; b < D; ++b) {
      deltaI += G[3 * a + b][i] * dx[b];
      deltaJ += G[3 * a + b][j] * dx[b];
    }
    slopeI += deltaI * dx[a];
    slopeJ += deltaJ * dx[a];
    approach += dv[a] * dx[a];
  }
  const double phi = slopeJ != 0.0 ? vanLeerLimiter(slopeI / slopeJ) : 0.0;
  return approach - 0.5 * phi * (slopeI + slopeJ);
}

}  // namespace ejecta
