#pragma once
// The solid's stress terms of the force pass: the in-plane components of sigma/(Omega rho s)
// (Lagrangian form) or sigma/rho (Interface form) of every particle, real and ghost, and in RZ the
// hoop stress sigma_theta_theta. The pair loop sums them into the divergence of the stress
// (sim/sph/hydro_force.cpp gives the two forms).
#include <array>
#include <vector>

#include "sim/solid/solid_state.hpp"
#include "sim/solid/strength.hpp"
#include "sim/sph/hydro_workspace.hpp"
#include "sim/sph/sph_options.hpp"
#include "sim/sph/terms/pair.hpp"
#include "sim/state/particles.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

// Stored index of the symmetric component (a, b).
inline constexpr int kSymIndex[3][3] = {{kXX, kXY, kXZ}, {kXY, kYY, kYZ}, {kXZ, kYZ, kZZ}};

// The stress that acts on particle i [Pa] (sim/solid/solid_state.hpp: the deviatoric stress less
// what its damage cracked, unless the yield surface already holds the damage, minus the
// pressure); a fluid particle (no shear modulus) carries its pressure alone.
inline SymTensor actingStress(const ParticleSet& p, const HydroWorkspace& ws, std::size_t i) {
  const int m = p.material[i];
  if (ws.shearModulus[m] > 0.0) return effectiveStress(p, i, ws.yieldCarriesDamage[m] != 0);
  SymTensor sigma;
  for (int c = 0; c < 3; ++c) sigma[c] -= p.P[i];
  return sigma;
}

template <int D, bool RZ>
struct StressDivergence {
  std::array<std::vector<double>, 6> T;  // sigma scaled for the momentum form, in-plane only
  std::vector<double> hoop;              // RZ: effective sigma_theta_theta [Pa]

  // T of the particles `which`; the rest (halos still in flight) come by refresh.
  StressDivergence(const ParticleSet& p, const HydroWorkspace& ws, MomentumForm form,
                   TermParticles which)
      : form_(form) {
    refresh(p, ws, which);
  }

  // Computes T and the hoop stress of the particles `which` (halos whose values arrived).
  void refresh(const ParticleSet& p, const HydroWorkspace& ws, TermParticles which) {
    const MomentumForm form = form_;
    const std::size_t n = p.size();
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) T[kSymIndex[a][b]].resize(n);
    if (RZ) hoop.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < which.count(); ++k) {
      const std::size_t i = which[k];
      const double sigmaI = RZ ? p.areaDensity[i] : p.rho[i];
      const double scale = form == MomentumForm::Lagrangian
                               ? 1.0 / (p.omega[i] * p.rho[i] * sigmaI)
                               : 1.0 / p.rho[i];
      const SymTensor sigma = actingStress(p, ws, i);
      for (int a = 0; a < D; ++a)
        for (int b = a; b < D; ++b) T[kSymIndex[a][b]][i] = scale * sigma[kSymIndex[a][b]];
      if constexpr (RZ) hoop[i] = sigma[kZZ];
    }
  }

 private:
  MomentumForm form_;
};

// The Jaumann rate of the deviatoric stress and the equivalent strain rate of particle i from its
// velocity gradient L (the one the energy equation used, so stress work and heating agree).
// A particle without strength (shear modulus 0) holds no deviatoric stress. `matrixShare`: the
// share of the strain its elastic part takes (a porous solid's compaction factor; its stress
// still rotates with the material).
inline void storeStressRate(ParticleSet& p, std::size_t i, const Mat3& L, double shearModulus,
                            double matrixShare = 1.0) {
  const int nc = p.stressComponents();
  if (shearModulus > 0.0) {
    SymTensor S;
    for (int c = 0; c < nc; ++c) S[c] = p.stress[c][i];
    const SymTensor rate = jaumannStressRate(L, S, shearModulus * matrixShare);
    for (int c = 0; c < nc; ++c) p.dstress_dt[c][i] = rate[c];
    p.strainRate[i] = equivalentStrainRate(L);
  } else {
    for (int c = 0; c < nc; ++c) p.dstress_dt[c][i] = 0.0;
    p.strainRate[i] = 0.0;
  }
}

}  // namespace ejecta
