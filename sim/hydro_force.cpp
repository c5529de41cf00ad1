#include "sim/hydro_force.hpp"

#include <algorithm>
#include <cmath>

namespace ejecta {

namespace {

template <template <int> class K, int D, bool RZ>
void forcePassImpl(ParticleSet& p, HydroWorkspace& ws) {
  const SphOptions& sph = ws.sph;
  const std::size_t nReal = p.numReal;
  const double alpha = sph.alpha, beta = sph.beta, eps = sph.epsilon;
  const double alphaU = sph.conductivity;
  const bool balsara = sph.balsara;

  // Balsara factor per particle (real and ghost share their source's divv/curlv).
  std::vector<double> shearFactor;
  if (balsara) {
    shearFactor.resize(p.size());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double div = std::abs(p.divv[i]);
      shearFactor[i] = div / (div + p.curlv[i] + 1e-4 * p.cs[i] / p.h[i] + 1e-300);
    }
  }
  // P / (omega rho sigma): sigma = rho (planar, 3D) or eta (RZ).
  std::vector<double> pressureTerm(p.size());
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double sigma = RZ ? p.areaDensity[i] : p.rho[i];
    pressureTerm[i] = p.P[i] / (p.omega[i] * p.rho[i] * sigma);
  }

  // Dynamic chunks balance uneven pair counts; each particle is summed by one thread alone.
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < nReal; ++i) {
    const double hi = p.h[i], reachI = kKernelSupport * hi;
    const double xi[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
    const double vi[3] = {p.v[0][i], p.v[1][i], p.v[2][i]};
    const double ci = p.cs[i], rhoI = p.rho[i], ui = p.u[i], Pi = p.P[i];
    const double sigmaI = RZ ? p.areaDensity[i] : rhoI;
    const double termI = pressureTerm[i];
    double acc[3] = {0.0, 0.0, 0.0};
    double dudtPressure = 0.0, dudtViscous = 0.0, dudtConduction = 0.0;

    for (std::uint32_t j : ws.lists.pairs(i)) {
      double dx[3] = {0.0, 0.0, 0.0}, dv[3] = {0.0, 0.0, 0.0};
      double r2 = 0.0, vdotx = 0.0;
      for (int d = 0; d < D; ++d) {
        dx[d] = xi[d] - p.x[d][j];
        dv[d] = vi[d] - p.v[d][j];
        r2 += dx[d] * dx[d];
        vdotx += dv[d] * dx[d];
      }
      if (r2 == 0.0) continue;
      const double r = std::sqrt(r2);
      const double hj = p.h[j];
      const double dWi = r < reachI ? kernelDerivative<K, D>(r, hi) : 0.0;
      const double dWj = r < kKernelSupport * hj ? kernelDerivative<K, D>(r, hj) : 0.0;
      const double dWavg = 0.5 * (dWi + dWj);
      const double mj = p.mass[j];

      // Monaghan viscosity, seed eqs. (1.6)-(1.7), acting only on approaching pairs.
      double visc = 0.0;
      const double cij = 0.5 * (ci + p.cs[j]);
      const double sigmaIJ = 0.5 * (sigmaI + (RZ ? p.areaDensity[j] : p.rho[j]));
      if (vdotx < 0.0) {
        const double hij = 0.5 * (hi + hj);
        const double mu = hij * vdotx / (r2 + eps * hij * hij);
        visc = (-alpha * cij * mu + beta * mu * mu) / sigmaIJ;
        if (balsara) visc *= 0.5 * (shearFactor[i] + shearFactor[j]);
      }

      // Force along x_ij / r.
      const double f = mj * (termI * dWi + pressureTerm[j] * dWj + visc * dWavg) / r;
      for (int d = 0; d < D; ++d) acc[d] -= f * dx[d];
      dudtPressure += mj * dWi * vdotx / r;
      dudtViscous += 0.5 * mj * visc * dWavg * vdotx / r;
      if (alphaU > 0.0) {
        const double rhoIJ = 0.5 * (rhoI + p.rho[j]);
        const double vsigU = std::sqrt(std::abs(Pi - p.P[j]) / rhoIJ);
        dudtConduction += mj * alphaU * vsigU * (ui - p.u[j]) / sigmaIJ * dWavg;
      }
    }

    double dudt = termI * dudtPressure + dudtViscous + dudtConduction;
    if constexpr (RZ) {
      // Hoop terms of the ring formulation (docs/rz.md).
      const double hoop = Pi * ws.dSmoothedR[i] / (rhoI * ws.smoothedR[i]);
      acc[0] += hoop;
      dudt -= hoop * vi[0];
    }
    for (int d = 0; d < 3; ++d) p.a[d][i] = d < D ? acc[d] : 0.0;
    p.du_dt[i] = dudt;
  }
}

}  // namespace

void runForcePass(ParticleSet& p, HydroWorkspace& ws) {
  dispatchHydro(ws, [&]<template <int> class K, int D, bool RZ>() {
    forcePassImpl<K, D, RZ>(p, ws);
  });
}

}  // namespace ejecta
