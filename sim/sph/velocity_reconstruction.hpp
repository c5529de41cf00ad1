#pragma once
// Limited linear reconstruction of velocities for the artificial viscosity's linear term
// (docs/undex.md, "The reconstructed viscosity").
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
#include <cmath>
#include <cstddef>
#include <vector>

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
  double adjugate[3][3] = {};
  double det, scale;
  if constexpr (D == 1) {
    det = M[0][0];
    scale = std::abs(M[0][0]);
    adjugate[0][0] = 1.0;
  } else if constexpr (D == 2) {
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    scale = 0.5 * std::abs(M[0][0] + M[1][1]);
    scale *= scale;
    adjugate[0][0] = M[1][1];
    adjugate[0][1] = -M[0][1];
    adjugate[1][0] = -M[1][0];
    adjugate[1][1] = M[0][0];
  } else {
    adjugate[0][0] = M[1][1] * M[2][2] - M[1][2] * M[2][1];
    adjugate[0][1] = M[0][2] * M[2][1] - M[0][1] * M[2][2];
    adjugate[0][2] = M[0][1] * M[1][2] - M[0][2] * M[1][1];
    adjugate[1][0] = M[1][2] * M[2][0] - M[1][0] * M[2][2];
    adjugate[1][1] = M[0][0] * M[2][2] - M[0][2] * M[2][0];
    adjugate[1][2] = M[0][2] * M[1][0] - M[0][0] * M[1][2];
    adjugate[2][0] = M[1][0] * M[2][1] - M[1][1] * M[2][0];
    adjugate[2][1] = M[0][1] * M[2][0] - M[0][0] * M[2][1];
    adjugate[2][2] = M[0][0] * M[1][1] - M[0][1] * M[1][0];
    det = M[0][0] * adjugate[0][0] + M[0][1] * adjugate[1][0] + M[0][2] * adjugate[2][0];
    scale = std::abs(M[0][0] + M[1][1] + M[2][2]) / 3.0;
    scale = scale * scale * scale;
  }
  // For a full, isotropic neighbourhood det = scale; along a free edge det/scale falls toward 0.
  // 1e-3 refuses neighbourhoods that are nearly a line (2D) or a plane (3D): a filament or a
  // sheet one particle thick, where the gradient across it is unknown.
  if (!(std::abs(det) > 1e-3 * scale)) return false;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      double sum = 0.0;
      for (int c = 0; c < D; ++c) sum += A[a][c] * adjugate[c][b];
      G[a][b] = sum / det;
    }
  return true;
}

// Barth & Jespersen's limiter on a particle's gradient (T. J. Barth & D. C. Jespersen,
// AIAA 89-0366, 1989): scales row a of G by phi_a in [0, 1] so that the velocity reconstructed to
// the midpoint of every pair, v_a,i + phi_a G_a . (x_j - x_i)/2, stays within [low_a, high_a], the
// range of v_a over the particle and its neighbours. `offsets` holds x_i - x_j for the `count`
// neighbours, D values each. phi_a is set by the neighbour the reconstruction moves furthest
// toward either bound, so only the extreme changes are needed; a particle at an extremum of v_a
// gets phi_a = 0.
template <int D>
void limitToNeighbourRange(double G[3][3], const double vi[3], const double low[3],
                           const double high[3], const double* offsets, std::size_t count) {
  double rise[3] = {0.0, 0.0, 0.0}, fall[3] = {0.0, 0.0, 0.0};  // largest change up and down
  for (std::size_t k = 0; k < count; ++k) {
    const double* dx = offsets + D * k;
    for (int a = 0; a < D; ++a) {
      double delta = 0.0;
      for (int b = 0; b < D; ++b) delta -= 0.5 * G[a][b] * dx[b];
      rise[a] = std::max(rise[a], delta);
      fall[a] = std::min(fall[a], delta);
    }
  }
  for (int a = 0; a < D; ++a) {
    double phi = 1.0;
    if (rise[a] > 0.0) phi = std::min(phi, (high[a] - vi[a]) / rise[a]);
    if (fall[a] < 0.0) phi = std::min(phi, (low[a] - vi[a]) / fall[a]);
    for (int b = 0; b < D; ++b) G[a][b] *= phi;
  }
}

// The limited slope of a pair: phi (s_i + s_j) / 2 with van Leer's limiter phi = 4 r / (1 + r)^2
// of the slopes' ratio r = s_i / s_j, which is 1 when they agree and falls to 0 as they differ by a
// large factor either way. Written as van Leer's harmonic mean 2 s_i s_j / (s_i + s_j): the same in
// exact arithmetic, and bit for bit symmetric in i and j, so the pair force conserves momentum to
// round-off. 0 when the slopes differ in sign (an extremum between the two) or either is 0.
inline double vanLeerSlope(double slopeI, double slopeJ) {
  const double product = slopeI * slopeJ;
  return product > 0.0 ? 2.0 * product / (slopeI + slopeJ) : 0.0;
}

// The pair's velocity difference after reconstruction to the midpoint, projected on dx:
//   (v_i* - v_j*) . dx = dv . dx - vanLeerSlope(s_i, s_j),   dx = x_i - x_j, dv = v_i - v_j,
// with the slopes s = dx . G dx of the two particles. Negative: the reconstructed velocities
// approach. Gi and Gj point to the particles' 3 x 3 gradients (row-major).
template <int D>
inline double reconstructedApproach(const double dx[3], const double dv[3], const double* Gi,
                                    const double* Gj) {
  double slopeI = 0.0, slopeJ = 0.0, approach = 0.0;
  for (int a = 0; a < D; ++a) {
    double deltaI = 0.0, deltaJ = 0.0;
    for (int b = 0; b < D; ++b) {
      deltaI += Gi[3 * a + b] * dx[b];
      deltaJ += Gj[3 * a + b] * dx[b];
    }
    slopeI += deltaI * dx[a];
    slopeJ += deltaJ * dx[a];
    approach += dv[a] * dx[a];
  }
  return approach - vanLeerSlope(slopeI, slopeJ);
}

// A particle's corrected, optionally range-limited velocity gradient, summed pair by pair over its
// gather list (the density pass; on time bins also the inactive particles an active one's pairs
// read, sim/sph/velocity_gradient_refresh.hpp): add() each neighbour with its pair weight f, then
// finish(). `offsets` is the caller's scratch (kept across particles to spare allocations).
template <int D>
class VelocityGradientSums {
 public:
  VelocityGradientSums(const double vi[3], bool monotone, std::vector<double>& offsets)
      : monotone_(monotone), offsets_(offsets) {
    offsets_.clear();  // x_i - x_j of the gather list, for the range limiter
    for (int a = 0; a < D; ++a) {
      vi_[a] = vLow_[a] = vHigh_[a] = vi[a];
    }
  }
  // Neighbour j at dx = x_i - x_j with dv = v_i - v_j, its velocity vj and the weight f.
  void add(const double dx[3], const double dv[3], const double vj[3], double f) {
    for (int a = 0; a < D; ++a) {
      for (int b = 0; b < D; ++b) gradSum_[a][b] += dv[a] * dx[b] * f;
      for (int b = a; b < D; ++b) shapeSum_[a][b] += dx[a] * dx[b] * f;  // symmetric
      if (monotone_) {
        vLow_[a] = std::min(vLow_[a], vj[a]);
        vHigh_[a] = std::max(vHigh_[a], vj[a]);
        offsets_.push_back(dx[a]);
      }
    }
  }
  // The gradient into out[9] (row-major dv_a/dx_b; 0 beyond D).
  void finish(double* out) {
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < a; ++b) shapeSum_[a][b] = shapeSum_[b][a];
    double G[3][3];
    correctedGradient<D>(gradSum_, shapeSum_, G);  // G = 0 where it cannot be inverted
    if (monotone_)
      limitToNeighbourRange<D>(G, vi_, vLow_, vHigh_, offsets_.data(), offsets_.size() / D);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) out[3 * a + b] = a < D && b < D ? G[a][b] : 0.0;
  }

 private:
  bool monotone_;
  std::vector<double>& offsets_;
  double vi_[3] = {}, vLow_[3] = {}, vHigh_[3] = {};
  double gradSum_[3][3] = {}, shapeSum_[3][3] = {};  // A and M of correctedGradient
};

}  // namespace ejecta
