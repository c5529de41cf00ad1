#include "sim/velocity_reconstruction.hpp"

#include <algorithm>

namespace ejecta {

namespace {

// Per velocity component a: the factor phi_a in [0, 1] that keeps v_a,i + phi_a G_a . (x_j - x_i)/2
// within [min_j v_a,j, max_j v_a,j] over the particle's pair list (itself included), applied to
// row a of G. A particle at a local extremum of v_a gets phi_a = 0: no reconstruction there.
template <int D>
void limitImpl(const ParticleSet& p, HydroWorkspace& ws) {
  std::array<std::vector<double>, 9>& G = ws.velocityGradient;
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    for (int a = 0; a < D; ++a) {
      const double vi = p.v[a][i];
      double lo = vi, hi = vi;
      for (std::uint32_t j : ws.lists.pairs(i)) {
        lo = std::min(lo, p.v[a][j]);
        hi = std::max(hi, p.v[a][j]);
      }
      double phi = 1.0;
      for (std::uint32_t j : ws.lists.pairs(i)) {
        double delta = 0.0;
        for (int b = 0; b < D; ++b) delta += 0.5 * G[3 * a + b][i] * (p.x[b][j] - p.x[b][i]);
        if (delta > 0.0) phi = std::min(phi, (hi - vi) / delta);
        else if (delta < 0.0) phi = std::min(phi, (lo - vi) / delta);
      }
      for (int b = 0; b < D; ++b) G[3 * a + b][i] *= phi;
    }
  }
}

}  // namespace

void limitVelocityGradients(const ParticleSet& p, HydroWorkspace& ws) {
  switch (ws.dim) {
    case 1: limitImpl<1>(p, ws); break;
    case 2: limitImpl<2>(p, ws); break;
    default: limitImpl<3>(p, ws); break;
  }
}

}  // namespace ejecta
