#include "sim/sph/velocity_gradient_refresh.hpp"

#include <cmath>
#include <cstdint>

#include "sim/sph/velocity_reconstruction.hpp"

namespace ejecta {

std::vector<std::size_t> inactivePartners(const ParticleSet& p, const HydroWorkspace& ws,
                                          const std::vector<std::size_t>& active) {
  // 0: not read, 1: read, 2: evaluated by the density pass (active).
  std::vector<unsigned char> mark(p.numReal, 0);
  for (std::size_t i : active) mark[i] = 2;
  for (std::size_t i : active)
    for (std::uint32_t j : ws.lists.pairs(i)) {
      const std::size_t ghost = j - p.numReal;  // wraps for real j: caught below
      const std::size_t real = j < p.numReal ? j
                               : ghost < p.ghostSource.size() ? p.ghostSource[ghost]
                                                              : p.numReal;  // a halo: not ours
      if (real < p.numReal && mark[real] == 0) mark[real] = 1;
    }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (mark[i] == 1) out.push_back(i);
  return out;
}

namespace {

template <template <int> class K, int D>
void refreshImpl(const ParticleSet& p, HydroWorkspace& ws,
                 const std::vector<std::size_t>& particles) {
  const bool monotone = ws.sph.viscosityReconstruction == ViscosityReconstruction::Monotone;
#pragma omp parallel
  {
    std::vector<std::uint32_t> cand;
    std::vector<double> offsets;
#pragma omp for schedule(dynamic, 256)
    for (std::size_t at = 0; at < particles.size(); ++at) {
      const std::size_t i = particles[at];
      const double xi[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
      const double vi[3] = {p.v[0][i], p.v[1][i], p.v[2][i]};
      const double hInv = 1.0 / p.h[i];
      cand.clear();
      ws.grid.query<D>(p, xi, kKernelSupport * p.h[i], cand);
      VelocityGradientSums<D> sums(vi, monotone, offsets);
      for (const std::uint32_t j : cand) {
        double dx[3] = {0.0, 0.0, 0.0}, dv[3] = {0.0, 0.0, 0.0}, vj[3] = {0.0, 0.0, 0.0};
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          dx[d] = xi[d] - p.x[d][j];
          vj[d] = p.v[d][j];
          dv[d] = vi[d] - vj[d];
          r2 += dx[d] * dx[d];
        }
        if (r2 == 0.0) continue;
        const double r = std::sqrt(r2);
        double w, dw;
        K<D>::shape(r * hInv, w, dw);
        sums.add(dx, dv, vj, p.mass[j] * dw / r);  // the density pass's weight: G is scale-free
      }
      sums.finish(&ws.velocityGradient[9 * i]);
    }
  }
}

}  // namespace

void refreshVelocityGradients(const ParticleSet& p, HydroWorkspace& ws,
                              const std::vector<std::size_t>& particles) {
  if (particles.empty()) return;
  dispatchHydro(ws, [&]<template <int> class K, int D, bool RZ>() {
    refreshImpl<K, D>(p, ws, particles);
  });
}

}  // namespace ejecta
