#include "sim/sph/density_pass.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sim/sph/velocity_reconstruction.hpp"

namespace ejecta {

namespace {

constexpr double kSearchMargin = 1.08;   // candidates fetched out to 1.08 x the support
constexpr double kNewtonTolerance = 1e-7;
constexpr int kNewtonMaxIterations = 60;
constexpr double kMaxGrowthPerStep = 2.0;  // h may change by at most this factor in one pass

template <int D>
double powD(double x) {
  if constexpr (D == 1) return x;
  else if constexpr (D == 2) return x * x;
  else return x * x * x;
}

// Sum of m_j W and m_j dW/dh over the candidates within the support of h (m_j r_j with the
// generalised volumes' weights r, when Weighted).
template <template <int> class K, int D, bool Weighted>
void kernelSums(const ParticleSet& p, const double* weight, const std::vector<std::uint32_t>& cand,
                const std::vector<double>& dist2, double h, double& S, double& dS) {
  S = 0.0;
  dS = 0.0;
  const double reach = kKernelSupport * h;
  const double reach2 = reach * reach;
  const double hInv = 1.0 / h;
  const double hInvD = powD<D>(hInv);
  for (std::size_t k = 0; k < cand.size(); ++k) {
    if (dist2[k] >= reach2) continue;
    const double r = std::sqrt(dist2[k]);
    const double m = Weighted ? p.mass[cand[k]] * weight[cand[k]] : p.mass[cand[k]];
    double w, dw;
    K<D>::shape(r * hInv, w, dw);
    S += m * w;
    dS -= m * (D * w + r * hInv * dw);
  }
  // W = sigma/h^D w(q), dW/dh = -sigma/h^(D+1) (D w + q w').
  const double norm = K<D>::sigma * hInvD;
  S *= norm;
  dS *= norm * hInv;
}

// Weighted: the generalised volumes (ws.volumeWeight; 1D/2D/3D), a template parameter so that
// the standard sums pay nothing for them.
template <template <int> class K, int D, bool RZ, bool Weighted>
std::optional<std::size_t> densityPassImpl(ParticleSet& p, HydroWorkspace& ws,
                                           const std::vector<std::size_t>* active) {
  const SphOptions& sph = ws.sph;
  const bool summation = sph.density == DensityMethod::Summation;
  const bool tiedH = densityPassSetsSmoothingLength(sph);
  const std::size_t nReal = p.numReal;
  const double etaD = powD<D>(sph.eta);
  const bool gradient = sph.viscosityReconstruction != ViscosityReconstruction::None;
  const bool monotone = sph.viscosityReconstruction == ViscosityReconstruction::Monotone;
  // Generalised volumes (1D/2D/3D, summation density): every sum below weighs j by m_j r_j in
  // place of m_j, so it is sum_j X_j W = X_i / V_i scaled by m_i / X_i; rho_i = S / r_i.
  static_assert(!(RZ && Weighted));
  const double* weight = Weighted ? ws.volumeWeight.data() : nullptr;
  if (Weighted && ws.volumeWeight.size() < p.size())
    throw std::logic_error("generalised volumes: a weight for every particle, ghosts included");
  std::size_t failedIndex = nReal;  // lowest failing index (a min reduction: schedule-proof)
  const std::size_t count = active ? active->size() : nReal;

#pragma omp parallel reduction(min : failedIndex)
  {
    const int t = omp_get_thread_num();
    std::vector<std::uint32_t> cand, list;
    std::vector<double> offsets;
    std::vector<double> dist2;  // squared distances: membership tests use r^2 < (2h)^2, as
                                // the neighbour lists do, so both agree at the support edge
    // Dynamic chunks balance the uneven cost (large-h particles, Newton iterations); each
    // particle is computed by one thread alone, so results do not depend on the schedule.
#pragma omp for schedule(dynamic, 256)
    for (std::size_t at = 0; at < count; ++at) {
      const std::size_t i = active ? (*active)[at] : at;
      const double xi[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
      const double mi = Weighted ? p.mass[i] * weight[i] : p.mass[i];
      const double hCap = ws.hCap ? ws.hCap[i] : std::numeric_limits<double>::infinity();
      const double hStart = std::min(p.h[i], hCap);
      double h = hStart;
      double radius = 0.0;
      auto fetch = [&](double needed) {
        radius = needed * kSearchMargin;
        cand.clear();
        ws.grid.query<D>(p, xi, radius, cand);
        dist2.resize(cand.size());
        for (std::size_t k = 0; k < cand.size(); ++k) {
          double r2 = 0.0;
          for (int d = 0; d < D; ++d) {
            const double dx = xi[d] - p.x[d][cand[k]];
            r2 += dx * dx;
          }
          dist2[k] = r2;
        }
      };
      fetch(kKernelSupport * h);

      if (tiedH) {
        // Newton iteration on f(h) = S(h) - m (eta/h)^D.
        for (int it = 0; it < kNewtonMaxIterations; ++it) {
          double S, dS;
          kernelSums<K, D, Weighted>(p, weight, cand, dist2, h, S, dS);
          const double target = mi * etaD / powD<D>(h);
          const double f = S - target;
          const double fp = dS + D * target / h;
          double hNew = (fp > 0.0 && std::isfinite(fp)) ? h - f / fp : h * (f > 0 ? 0.8 : 1.25);
          hNew = std::clamp(hNew, std::max(0.5 * h, hStart / kMaxGrowthPerStep),
                            std::min(2.0 * h, hStart * kMaxGrowthPerStep));
          hNew = std::min(hNew, hCap);  // == hCap exactly when the cap holds it
          const bool converged = std::abs(hNew - h) < kNewtonTolerance * h;
          h = hNew;
          if (kKernelSupport * h > radius) fetch(kKernelSupport * h);
          if (converged) break;
        }
      }

      // Final sums at h: density, grad-h term, gather list, divergence, curl, continuity rate.
      const double reach = kKernelSupport * h;
      const double reach2 = reach * reach;
      const double hInv = 1.0 / h;
      double S = 0.0, dS = 0.0, vdotgrad = 0.0;
      double curl[3] = {0.0, 0.0, 0.0};
      const double vi[3] = {p.v[0][i], p.v[1][i], p.v[2][i]};
      VelocityGradientSums<D> velocityGradient(vi, monotone, offsets);
      list.clear();
      for (std::size_t k = 0; k < cand.size(); ++k) {
        if (dist2[k] >= reach2) continue;
        const double r = std::sqrt(dist2[k]);
        const std::uint32_t j = cand[k];
        list.push_back(j);
        const double m = Weighted ? p.mass[j] * weight[j] : p.mass[j];
        double w, dw;
        K<D>::shape(r * hInv, w, dw);
        S += m * w;
        dS -= m * (D * w + r * hInv * dw);
        if (r == 0.0) continue;
        const double f = m * dw / r;  // grad W = x_ij f sigma / (m h^(D+1)), scaled below
        double dx[3] = {0.0, 0.0, 0.0}, dv[3] = {0.0, 0.0, 0.0}, vj[3] = {0.0, 0.0, 0.0};
        for (int d = 0; d < D; ++d) {
          dx[d] = xi[d] - p.x[d][j];
          vj[d] = p.v[d][j];
          dv[d] = vi[d] - vj[d];
          vdotgrad += dv[d] * dx[d] * f;
        }
        if (gradient) velocityGradient.add(dx, dv, vj, f);
        if constexpr (D == 2) {
          curl[2] += (dv[0] * dx[1] - dv[1] * dx[0]) * f;
        } else if constexpr (D == 3) {
          curl[0] += (dv[1] * dx[2] - dv[2] * dx[1]) * f;
          curl[1] += (dv[2] * dx[0] - dv[0] * dx[2]) * f;
          curl[2] += (dv[0] * dx[1] - dv[1] * dx[0]) * f;
        }
      }
      {
        // Kernel normalisation applied once: W = sigma/h^D w, dW/dr = sigma/h^(D+1) w',
        // dW/dh = -sigma/h^(D+1) (D w + q w').
        const double norm = K<D>::sigma * powD<D>(hInv);
        S *= norm;
        dS *= norm * hInv;
        vdotgrad *= norm * hInv;
        for (double& c : curl) c *= norm * hInv;
      }
      if (gradient) velocityGradient.finish(&ws.velocityGradient[9 * i]);
      ws.lists.storeGather(t, i, list.data(), list.size());
      ws.neighbourCount[i] = static_cast<std::uint32_t>(list.size());
      p.h[i] = h;

      double rt = 1.0, drt = 0.0;
      if constexpr (RZ) ws.axis->smoothedRadius(xi[0], h, rt, drt);
      // The density-like quantity of the kernel sums: rho (1D, 2D, 3D) or eta = 2 pi rt rho (RZ).
      // At its cap h no longer follows the density. Under continuity density h reaches it from
      // a floored density (rounded: within 1e-3); with h tied to the kernel sum, by the clamp.
      const bool capped = tiedH ? h == hCap : h >= hCap * (1.0 - 1e-3);
      double sigma;
      if (summation) {
        sigma = S;
        p.rho[i] = RZ ? S / (2.0 * std::numbers::pi * rt) : S;
        if constexpr (Weighted) p.rho[i] /= weight[i];  // m_i sum_j X_j W / X_i
      } else {
        sigma = RZ ? 2.0 * std::numbers::pi * rt * p.rho[i] : p.rho[i];
      }
      if (!(sigma > 0.0)) {
        failedIndex = std::min(failedIndex, i);
        continue;
      }
      // A capped h does not follow the density: no grad-h term (omega = 1).
      double omega = tiedH && !capped ? 1.0 + h / (D * sigma) * dS : 1.0;
      if constexpr (RZ) {
        // rho = eta / (2 pi rt(h)) also depends on h through rt: with h tied to eta the
        // Lagrangian's d rho carries f = 1 + (rt - r rt') / (2 rt) (1.5 on the axis, 1 beyond
        // 2h), folded into omega.
        if (tiedH && !capped) omega /= 1.0 + (rt - xi[0] * drt) / (2.0 * rt);
      }
      p.omega[i] = omega;
      if constexpr (RZ) {
        p.areaDensity[i] = sigma;
        ws.smoothedR[i] = rt;
        ws.dSmoothedR[i] = drt;
      }
      const double hoopRate = RZ ? p.v[0][i] * drt / rt : 0.0;  // v_r / r term of div v
      // A particle held at its cap under continuity density has rarefied below what its kernel
      // holds (why h reached the cap): its own small density would divide its neighbours' mass
      // flux, giving a divergence far beyond any velocity in the run and a continuity rate that
      // drives it through zero in a step. Its flow quantities divide by the kernel sum instead:
      // its density then changes at the rate its neighbours' divergence gives.
      const double flow = capped && !summation ? std::max(S, sigma) : sigma;
      p.divv[i] = -vdotgrad / (omega * flow) + hoopRate;
      p.curlv[i] = std::sqrt(curl[0] * curl[0] + curl[1] * curl[1] + curl[2] * curl[2]) /
                   (omega * flow);
      // Continuity rate, also what drives the seed's dh/dt.
      const double drho = p.rho[i] / flow * vdotgrad - p.rho[i] * hoopRate;
      p.drho_dt[i] = drho;
      p.dh_dt[i] = sph.smoothingLength == SmoothingLengthMethod::Seed
                       ? -sph.relaxation * h / (p.rho[i] * D) * drho
                       : 0.0;
      if (capped) p.dh_dt[i] = std::min(p.dh_dt[i], 0.0);
    }
  }
  return failedIndex < nReal ? std::optional<std::size_t>(failedIndex) : std::nullopt;
}

}  // namespace

std::optional<std::size_t> runDensityPass(ParticleSet& p, HydroWorkspace& ws,
                                          const std::vector<std::size_t>* active) {
  ws.neighbourCount.resize(p.numReal);
  const bool rz = ws.geometry == Geometry::Axisymmetric;
  if (ws.sph.viscosityReconstruction != ViscosityReconstruction::None) {
    if (!active) ws.velocityGradient.assign(9 * p.size(), 0.0);  // components beyond D stay 0
    else ws.velocityGradient.resize(9 * p.size(), 0.0);  // the others keep their last tensor
  }
  if (rz) {
    ws.smoothedR.resize(p.size());
    ws.dSmoothedR.resize(p.size());
  }
  if (active && rz) {
    // The particles the pass skips keep their density and h as predicted; their smoothed radius
    // and ring area density follow from those at the present position.
    std::vector<unsigned char> inPass(p.numReal, 0);
    for (std::size_t i : *active) inPass[i] = 1;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < p.numReal; ++i) {
      if (inPass[i]) continue;
      ws.axis->smoothedRadius(p.x[0][i], p.h[i], ws.smoothedR[i], ws.dSmoothedR[i]);
      p.areaDensity[i] = 2.0 * std::numbers::pi * ws.smoothedR[i] * p.rho[i];
    }
  }
  const bool weighted = !ws.volumeWeight.empty();
  if (weighted && rz) throw std::logic_error("generalised volumes are built for 1D, 2D and 3D");
  return dispatchHydro(ws, [&]<template <int> class K, int D, bool RZ>() {
    if constexpr (!RZ)
      if (weighted) return densityPassImpl<K, D, false, true>(p, ws, active);
    return densityPassImpl<K, D, RZ, false>(p, ws, active);
  });
}

std::vector<double> volumeWeightsOf(const ParticleSet& p, double exponent) {
  std::vector<double> r(p.numReal);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i)
    r[i] = std::pow(p.mass[i], exponent - 1.0) * std::pow(p.rho[i], -exponent);
  return r;
}

void placeVolumeWeights(const ParticleSet& p, const std::vector<double>& real, HydroWorkspace& ws) {
  ws.volumeWeight.resize(p.size());
  std::copy(real.begin(), real.end(), ws.volumeWeight.begin());
  for (std::size_t g = p.numReal; g < p.size(); ++g)
    ws.volumeWeight[g] = real[p.ghostSource[g - p.numReal]];
}

void setSmoothingFromDensity(ParticleSet& p, const HydroWorkspace& ws) {
  const int D = ws.dim;
  const bool rz = ws.geometry == Geometry::Axisymmetric;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    // RZ: the 2D area per particle is m / (2 pi rt rho), rt the smoothed radius at the current h
    // (finite on the axis), as in the density pass.
    double perVolume = p.rho[i];
    if (rz) {
      double rt, drt;
      ws.axis->smoothedRadius(p.x[0][i], p.h[i], rt, drt);
      perVolume = 2.0 * std::numbers::pi * rt * p.rho[i];
    }
    const double volume = p.mass[i] / perVolume;
    // The D-th root without pow: this runs for every particle at every sub-step of individual
    // steps, and pow was 8% of a blast's run time on bins.
    p.h[i] = ws.sph.eta * (D == 1 ? volume : D == 2 ? std::sqrt(volume) : std::cbrt(volume));
    if (ws.hCap) p.h[i] = std::min(p.h[i], ws.hCap[i]);
  }
}

}  // namespace ejecta
