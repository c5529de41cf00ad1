// The force pass: accelerations and energy rates from the stress (pressure alone for fluids,
// pressure plus deviatoric stress for solids), artificial viscosity and conductivity, and for
// solids the velocity gradient that drives the stress rate (docs/design.md, docs/materials.md).
//
// The pair force is the divergence of the stress in one of two forms (SphOptions::form), each
// with the energy equation that is its exact conjugate, so total energy is conserved:
//   Lagrangian: a_i = sum_j m_j [T_i dW_i + T_j dW_j],   T = sigma / (Omega rho s)
//   Interface:  a_i = sum_j m_j [sigma_i/(rho_i s_j) + sigma_j/(rho_j s_i)] dW_ij
// where s is rho (1D, 2D, 3D) or the ring area density eta = 2 pi r rho (RZ), and
//   du_i/dt = sigma_i : L_i / rho_i,  L_i = -sum_j w_ij v_ij (x) grad W
// with the same weights w (m_j/(Omega_i s_i) with grad W(h_i), or m_j/s_j with the averaged
// gradient), so L_i is also the velocity gradient the stress rate uses.
#include "sim/sph/hydro_force.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/solid/strength.hpp"
#include "sim/state/tensor.hpp"
#include "sim/sph/velocity_reconstruction.hpp"

namespace ejecta {

namespace {

// Stored index of the symmetric component (a, b).
constexpr int kSymIndex[3][3] = {{kXX, kXY, kXZ}, {kXY, kYY, kYZ}, {kXZ, kYZ, kZZ}};

// Per-particle stress terms of the pair loop: the in-plane components of sigma/(Omega rho s)
// (Lagrangian) or sigma/rho (Interface), the hoop stress (RZ), and the artificial stress R.
struct StressTerms {
  std::array<std::vector<double>, 6> T;
  std::array<std::vector<double>, 6> R;
  std::vector<double> hoop;  // RZ: effective sigma_theta_theta [Pa]
  bool artificial = false;
};

template <int D, bool RZ, MomentumForm Form>
void buildStressTerms(const ParticleSet& p, const HydroWorkspace& ws, StressTerms& st) {
  const std::size_t n = p.size();
  const int nc = p.stressComponents();
  for (int a = 0; a < D; ++a)
    for (int b = a; b < D; ++b) st.T[kSymIndex[a][b]].resize(n);
  if (RZ) st.hoop.resize(n);
  st.artificial = ws.artificialStress > 0.0;
  if (st.artificial)
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) st.R[kSymIndex[a][b]].assign(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const double sigmaI = RZ ? p.areaDensity[i] : p.rho[i];
    const double scale = Form == MomentumForm::Lagrangian
                             ? 1.0 / (p.omega[i] * p.rho[i] * sigmaI)
                             : 1.0 / p.rho[i];
    const bool solid = ws.shearModulus[p.material[i]] > 0.0;
    // Damage (Grady-Kipp, principal-stress failure) removes the deviatoric stress it cracks,
    // unless the yield surface already holds it (Collins: S sits on (1 - D) Y_i + D Y_d).
    const double intact =
        !solid ? 0.0 : ws.yieldCarriesDamage[p.material[i]] ? 1.0 : 1.0 - p.damage(i);
    SymTensor sigma;
    for (int c = 0; c < nc; ++c) sigma[c] = intact * p.stress[c][i];
    for (int c = 0; c < 3; ++c) sigma[c] -= p.P[i];
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) st.T[kSymIndex[a][b]][i] = scale * sigma[kSymIndex[a][b]];
    if constexpr (RZ) st.hoop[i] = sigma[kZZ];
    if (!st.artificial || !solid) continue;
    // Artificial stress (Monaghan 2000, Gray et al. 2001 eqs. 4.6-4.8): in the principal frame
    // R = -epsilon sigma / (rho s) for each tensile principal stress, rotated back.
    const double eps = ws.artificialStress / (p.rho[i] * sigmaI);
    if constexpr (D == 1) {
      st.R[kXX][i] = sigma[kXX] > 0.0 ? -eps * sigma[kXX] : 0.0;
    } else if constexpr (D == 2) {
      double lo, hi, c, s;
      planeEigen(sigma[kXX], sigma[kYY], sigma[kXY], lo, hi, c, s);
      const double rHi = hi > 0.0 ? -eps * hi : 0.0, rLo = lo > 0.0 ? -eps * lo : 0.0;
      // Eigenvector of hi is (c, s), of lo (-s, c).
      st.R[kXX][i] = rHi * c * c + rLo * s * s;
      st.R[kYY][i] = rHi * s * s + rLo * c * c;
      st.R[kXY][i] = (rHi - rLo) * c * s;
    } else {
      std::array<double, 3> values;
      Mat3 vectors;
      symmetricEigen(sigma, values, &vectors);
      if (values[2] <= 0.0) continue;
      for (int k = 0; k < 6; ++k) {
        double sum = 0.0;
        for (int e = 0; e < 3; ++e)
          if (values[e] > 0.0)
            sum += -eps * values[e] * vectors[kSymRow[k]][e] * vectors[kSymCol[k]][e];
        st.R[k][i] = sum;
      }
    }
  }
}

template <template <int> class K, int D, bool RZ, MomentumForm Form, bool Solid>
void forcePassImpl(ParticleSet& p, HydroWorkspace& ws) {
  const SphOptions& sph = ws.sph;
  const std::size_t nReal = p.numReal;
  const double alpha = sph.alpha, beta = sph.beta, eps = sph.epsilon;
  const double alphaU = sph.conductivity;
  const bool balsara = sph.balsara;
  const bool evolveAlpha = sph.viscositySwitch != ViscositySwitch::None;
  const bool reconstruct = sph.viscosityReconstruction != ViscosityReconstruction::None;
  const double betaPerAlpha = alpha > 0.0 ? beta / alpha : 0.0;  // keeps the scene's ratio
  constexpr bool kInterface = Form == MomentumForm::Interface;
  const bool continuityHere = kInterface && sph.density == DensityMethod::Continuity;

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
  // Switch: alpha of every particle, a ghost taking its source's (the ghost build leaves it 0).
  std::vector<double> alphaOf;
  if (evolveAlpha) {
    if (!p.hasViscositySwitch())
      throw std::logic_error("viscosity switch on but the particles carry no alpha");
    alphaOf.resize(p.size());
    for (std::size_t i = 0; i < nReal; ++i) alphaOf[i] = p.alpha[i];
    for (std::size_t g = nReal; g < p.size(); ++g) alphaOf[g] = p.alpha[p.ghostSource[g - nReal]];
  }
  // Fluids: P/(Omega rho s) (Lagrangian) or P/rho (Interface). Solids: the stress terms.
  std::vector<double> pressureTerm;
  StressTerms st;
  if constexpr (Solid) {
    buildStressTerms<D, RZ, Form>(p, ws, st);
  } else {
    pressureTerm.resize(p.size());
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double sigma = RZ ? p.areaDensity[i] : p.rho[i];
      pressureTerm[i] = kInterface ? p.P[i] / p.rho[i]
                                   : p.P[i] / (p.omega[i] * p.rho[i] * sigma);
    }
  }
  const bool artificial = Solid && st.artificial;
  const double artificialN = sph.artificialStressExponent;
  // f^n is evaluated for every pair: an integer n (the default 4) is a few multiplications,
  // where std::pow cost a fifth of a solid step.
  const int artificialIntN = static_cast<int>(artificialN);
  const bool integerN = artificialIntN == artificialN && artificialIntN <= 16;
  auto fPower = [=](double f) {
    if (!integerN) return std::pow(f, artificialN);
    double out = 1.0, base = f;
    for (int e = artificialIntN; e > 0; e >>= 1, base *= base)
      if (e & 1) out *= base;
    return out;
  };
  double wRef = 1.0, dwRef;
  K<D>::shape(1.0 / sph.eta, wRef, dwRef);  // f = W(r)/W(dp), dp = h/eta: the spacing

  // Dynamic chunks balance uneven pair counts; each particle is summed by one thread alone.
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < nReal; ++i) {
    const double hi = p.h[i], reachI = kKernelSupport * hi;
    const double xi[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
    const double vi[3] = {p.v[0][i], p.v[1][i], p.v[2][i]};
    const double ci = p.cs[i], rhoI = p.rho[i], ui = p.u[i], Pi = p.P[i];
    const double sigmaI = RZ ? p.areaDensity[i] : rhoI;
    const double lagrangeWeight = 1.0 / (p.omega[i] * sigmaI);
    double acc[3] = {0.0, 0.0, 0.0};
    double grad[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};  // -L_i
    double dudtDivergence = 0.0, dudtViscous = 0.0, dudtConduction = 0.0;
    const double* gradientI = reconstruct ? &ws.velocityGradient[9 * i] : nullptr;

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
      const double r = std::sqrt(r2), rInv = 1.0 / r;
      const double hj = p.h[j];
      const double dWi = r < reachI ? kernelDerivative<K, D>(r, hi) : 0.0;
      const double dWj = r < kKernelSupport * hj ? kernelDerivative<K, D>(r, hj) : 0.0;
      const double dWavg = 0.5 * (dWi + dWj);
      const double mj = p.mass[j];
      const double sigmaJ = RZ ? p.areaDensity[j] : p.rho[j];

      // Monaghan viscosity, seed eqs. (1.6)-(1.7), acting only on approaching pairs.
      double visc = 0.0;
      const double cij = 0.5 * (ci + p.cs[j]);
      const double sigmaIJ = 0.5 * (sigmaI + sigmaJ);
      if (vdotx < 0.0) {
        const double hij = 0.5 * (hi + hj);
        const double mu = hij * vdotx / (r2 + eps * hij * hij);
        // Reconstructed: the linear term sees the approach of the velocities carried to the
        // midpoint, kept between the raw approach and zero, so the reconstruction only ever takes
        // viscosity away and the force stays continuous as a pair turns from approaching to
        // receding (test: the quarter box). The quadratic term keeps the raw approach: it is the
        // strong-shock term (negligible at a weak shock, where the linear term's width is the
        // problem), and without it the noise behind a strong blast grows (docs/undex.md).
        const double muLinear =
            reconstruct
                ? mu * std::clamp(reconstructedApproach<D>(dx, dv, gradientI,
                                                           &ws.velocityGradient[9 * j]) / vdotx,
                                  0.0, 1.0)
                : mu;
        const double alphaIJ = evolveAlpha ? 0.5 * (alphaOf[i] + alphaOf[j]) : alpha;
        const double betaIJ = evolveAlpha ? betaPerAlpha * alphaIJ : beta;
        visc = (-alphaIJ * cij * muLinear + betaIJ * mu * mu) / sigmaIJ;
        if (balsara) visc *= 0.5 * (shearFactor[i] + shearFactor[j]);
      }
      const double fVisc = mj * visc * dWavg * rInv;
      for (int d = 0; d < D; ++d) acc[d] -= fVisc * dx[d];
      dudtViscous += 0.5 * fVisc * vdotx;

      // Weight of this pair in the velocity gradient (and the energy equation).
      const double wGrad = kInterface ? mj / sigmaJ * dWavg * rInv
                                      : mj * lagrangeWeight * dWi * rInv;
      if constexpr (Solid) {
        double wI, wJ;  // factors of T_i and T_j in the pair force
        if constexpr (kInterface) {
          wI = mj / sigmaJ * dWavg * rInv;
          wJ = mj / sigmaI * dWavg * rInv;
        } else {
          wI = mj * dWi * rInv;
          wJ = mj * dWj * rInv;
        }
        double fArt = 0.0;
        if (artificial) {
          double w, dw;
          K<D>::shape(2.0 * r / (hi + hj), w, dw);
          fArt = mj * fPower(w / wRef) * dWavg * rInv;
        }
        for (int a = 0; a < D; ++a) {
          double sum = 0.0;
          for (int b = 0; b < D; ++b) {
            const int k = kSymIndex[a][b];
            sum += (wI * st.T[k][i] + wJ * st.T[k][j]) * dx[b];
            if (artificial) {
              const double rij = (st.R[k][i] + st.R[k][j]) * fArt;
              sum += rij * dx[b];
              dudtViscous -= 0.5 * dv[a] * rij * dx[b];
            }
            grad[a][b] += wGrad * dv[a] * dx[b];
          }
          acc[a] += sum;
        }
      } else {
        double f;
        if constexpr (kInterface) {
          f = mj * (pressureTerm[i] / sigmaJ + pressureTerm[j] / sigmaI) * dWavg * rInv;
        } else {
          f = mj * (pressureTerm[i] * dWi + pressureTerm[j] * dWj) * rInv;
        }
        for (int d = 0; d < D; ++d) acc[d] -= f * dx[d];
        dudtDivergence += wGrad * vdotx;
      }
      if (alphaU > 0.0) {
        const double rhoIJ = 0.5 * (rhoI + p.rho[j]);
        const double vsigU = std::sqrt(std::abs(Pi - p.P[j]) / rhoIJ);
        dudtConduction += mj * alphaU * vsigU * (ui - p.u[j]) / sigmaIJ * dWavg;
      }
    }

    // Hoop rate v_r / r of RZ, with the smoothed radius near the axis (docs/rz.md).
    const double hoopRate = RZ ? vi[0] * ws.dSmoothedR[i] / ws.smoothedR[i] : 0.0;
    double dudt = dudtViscous + dudtConduction;
    double divergence;  // div v of the pair weights, for the continuity density
    if constexpr (Solid) {
      Mat3 L{};
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) L[a][b] = -grad[a][b];
      if constexpr (RZ) {
        L[2][2] = hoopRate;
        acc[0] -= st.hoop[i] * ws.dSmoothedR[i] / (rhoI * ws.smoothedR[i]);
      }
      // sigma_i : L_i / rho_i, with sigma recovered from T (scale undone).
      const double unscale = kInterface ? 1.0 : p.omega[i] * sigmaI;
      double power = 0.0;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) power += st.T[kSymIndex[a][b]][i] * unscale * L[a][b];
      if constexpr (RZ) power += st.hoop[i] * L[2][2] / rhoI;
      dudt += power;
      divergence = L[0][0] + L[1][1] + L[2][2];
      const double G = ws.shearModulus[p.material[i]];
      const int nc = p.stressComponents();
      if (G > 0.0) {
        SymTensor S;
        for (int c = 0; c < nc; ++c) S[c] = p.stress[c][i];
        const SymTensor rate = jaumannStressRate(L, S, G);
        for (int c = 0; c < nc; ++c) p.dstress_dt[c][i] = rate[c];
        p.strainRate[i] = equivalentStrainRate(L);
      } else {
        for (int c = 0; c < nc; ++c) p.dstress_dt[c][i] = 0.0;
        p.strainRate[i] = 0.0;
      }
    } else {
      // P_i/rho_i sum_j w_ij v_ij . grad W = -(P_i/rho_i) (div v)_i
      divergence = -dudtDivergence + hoopRate;
      dudt += Pi / rhoI * dudtDivergence;
      if constexpr (RZ) {
        const double hoop = Pi * ws.dSmoothedR[i] / (rhoI * ws.smoothedR[i]);
        acc[0] += hoop;
        dudt -= hoop * vi[0];
      }
    }
    if (continuityHere) {
      // Volume-weighted continuity, d rho/dt = -rho div v with the pair weights m_j/s_j, which
      // does not see the neighbour's density jump at an interface.
      p.drho_dt[i] = -rhoI * divergence;
      if (sph.smoothingLength == SmoothingLengthMethod::Seed)
        p.dh_dt[i] = -sph.relaxation * hi / (rhoI * D) * p.drho_dt[i];
    }
    for (int d = 0; d < 3; ++d) p.a[d][i] = d < D ? acc[d] : 0.0;
    p.du_dt[i] = dudt;
    if (evolveAlpha) {
      // Morris & Monaghan (1997) with the (alpha_max - alpha) source of Rosswog et al.
      // (2000): decay over tau = h/(l c), growth where the flow converges.
      const double alphaI = p.alpha[i];
      p.dalpha_dt[i] = -(alphaI - sph.alphaMin) * sph.alphaDecay * ci / hi +
                       std::max(-p.divv[i], 0.0) * (alpha - alphaI);
    }
  }
}

}  // namespace

void initialiseViscosityAlpha(ParticleSet& p, const SphOptions& sph) {
  if (sph.viscositySwitch == ViscositySwitch::None || p.hasViscositySwitch()) return;
  p.enableViscositySwitch(sph.alphaMin);
  if (!p.hasBurn()) return;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (std::isfinite(p.lightingTime[i])) p.alpha[i] = sph.alpha;
}

void runForcePass(ParticleSet& p, HydroWorkspace& ws) {
  const bool solid = p.stressComponents() > 0;
  const MomentumForm form = ws.sph.form;
  dispatchHydro(ws, [&]<template <int> class K, int D, bool RZ>() {
    if (form == MomentumForm::Interface) {
      if (solid) forcePassImpl<K, D, RZ, MomentumForm::Interface, true>(p, ws);
      else forcePassImpl<K, D, RZ, MomentumForm::Interface, false>(p, ws);
    } else {
      if (solid) forcePassImpl<K, D, RZ, MomentumForm::Lagrangian, true>(p, ws);
      else forcePassImpl<K, D, RZ, MomentumForm::Lagrangian, false>(p, ws);
    }
  });
}

}  // namespace ejecta
