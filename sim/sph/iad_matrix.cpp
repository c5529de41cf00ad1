#include "sim/sph/iad_matrix.hpp"

#include <cmath>

#include "sim/sph/kernel.hpp"

namespace ejecta {

namespace {

// det(tau) over the product of its diagonal: 1 for neighbours spread evenly in every direction,
// 0 for neighbours on a line (2D) or a plane (3D). Below this the inverse would amplify the
// neighbours' scatter across the thin direction into forces far beyond the kernel gradient's (a
// filament, a fragment of a few particles), so the particle keeps the kernel gradient.
constexpr double kWellConditioned = 1e-4;

}  // namespace

template <int D>
bool invertSymmetric(const double tau[9], double C[9]) {
  for (int k = 0; k < 9; ++k) C[k] = 0.0;
  const double a = tau[0], b = tau[1], c = tau[2], d = tau[4], e = tau[5], f = tau[8];
  if constexpr (D == 1) {
    if (!(a > 0.0)) return false;
    C[0] = 1.0 / a;
    return true;
  } else if constexpr (D == 2) {
    const double det = a * d - b * b;
    if (!(det > kWellConditioned * a * d)) return false;
    C[0] = d / det;
    C[1] = C[3] = -b / det;
    C[4] = a / det;
    return true;
  } else {
    // Cofactors of [[a b c] [b d e] [c e f]].
    const double A = d * f - e * e, B = c * e - b * f, Cc = b * e - c * d;
    const double det = a * A + b * B + c * Cc;
    if (!(det > kWellConditioned * a * d * f)) return false;
    C[0] = A / det;
    C[1] = C[3] = B / det;
    C[2] = C[6] = Cc / det;
    C[4] = (a * f - c * c) / det;
    C[5] = C[7] = (b * c - a * e) / det;
    C[8] = (a * d - b * b) / det;
    return true;
  }
}

template bool invertSymmetric<1>(const double[9], double[9]);
template bool invertSymmetric<2>(const double[9], double[9]);
template bool invertSymmetric<3>(const double[9], double[9]);

namespace {

template <template <int> class K, int D>
void fill(const ParticleSet& p, HydroWorkspace& ws) {
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double h = p.h[i];
    double tau[9] = {};
    for (std::uint32_t j : ws.lists.gather(i)) {
      double dx[3] = {0.0, 0.0, 0.0}, r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        dx[d] = p.x[d][j] - p.x[d][i];
        r2 += dx[d] * dx[d];
      }
      if (r2 == 0.0) continue;
      const double weight = p.mass[j] / p.rho[j] * kernelValue<K, D>(std::sqrt(r2), h);
      for (int a = 0; a < D; ++a)
        for (int b = a; b < D; ++b) tau[3 * a + b] += weight * dx[a] * dx[b];
    }
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < a; ++b) tau[3 * a + b] = tau[3 * b + a];
    invertSymmetric<D>(tau, &ws.iadMatrix[9 * i]);
  }
}

}  // namespace

void computeIadMatrices(const ParticleSet& p, HydroWorkspace& ws) {
  ws.iadMatrix.assign(9 * p.size(), 0.0);
  dispatchHydro(ws, [&]<template <int> class K, int D, bool RZ>() { fill<K, D>(p, ws); });
}

}  // namespace ejecta
