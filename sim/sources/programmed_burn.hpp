#pragma once
// Programmed burn of a JWL explosive (docs/sources.md). Each explosive particle is lit when the
// detonation front, running at the C-J velocity D from the initiation point or line, reaches it:
//   t_L = t_init + |x - x_init| / D.
// Its burn fraction then rises linearly to 1 while the front crosses the particle,
//   F = min(1, (t - t_L) D / (1.5 dx)),   dx = h / eta (the particle spacing),
// the lighting-time burn of Wilkins' HEMP and LS-DYNA's *MAT_HIGH_EXPLOSIVE_BURN (F1 = 2 (t - t_L)
// D A_emax / (3 V_e), LS-DYNA Theory Manual, sec. 19.8: 1.5 cell widths for a cube). As there, the
// fraction is at least the compression ("beta") burn F2 = (1 - V) / (1 - V_CJ), V = rho0 / rho the
// relative volume and V_CJ = 1 - p_CJ / (rho0 D^2) its C-J value: explosive squeezed ahead of the
// front (which, unburnt, has no pressure to resist) burns as it is compressed, instead of being
// crushed past the C-J density over long runs of the front. The JWL pressure is multiplied by F;
// the chemical energy e0 is in the particle's internal energy from t = 0, so the energy ledger
// counts the yield as the explosive's initial internal energy.
#include <vector>

#include "sim/solid/materials.hpp"
#include "sim/state/particle_mask.hpp"
#include "sim/state/particles.hpp"
#include "sim/sources/source_specs.hpp"
#include "sim/state/geometry.hpp"

namespace ejecta {

// Detonation velocity [m/s] of each material: the scene's velocity or the explosive's C-J
// velocity for detonated materials, 0 for the others.
std::vector<double> burnVelocities(const std::vector<DetonationSpec>& detonations,
                                   const MaterialTable& materials);

// What the burn needs per material (index = material): velocity 0 = not detonated.
struct BurnTable {
  std::vector<double> velocity;          // detonation velocity D [m/s] (burnVelocities)
  std::vector<double> rho0;              // unreacted density [kg/m^3]; 0: no compression burn
  std::vector<double> cjRelativeVolume;  // V_CJ = 1 - p_CJ / (rho0 D_CJ^2) of the JWL's C-J state
};
// Throws SceneError as burnVelocities does.
BurnTable burnTable(const std::vector<DetonationSpec>& detonations, const MaterialTable& materials);

// Allocates the burn arrays and sets every explosive particle's lighting time from its initial
// position (the earliest over the material's detonations). Does nothing without detonations.
void assignLightingTimes(const std::vector<DetonationSpec>& detonations, Geometry geometry,
                         const MaterialTable& materials, ParticleSet& p);

// Advances the burn fractions to time t (never decreasing): max(F, F1, F2), and scales the pressure
// of the real explosive particles by them. eta is the scene's h = eta dx.
void applyProgrammedBurn(ParticleSet& p, const BurnTable& burn, double eta, double t,
                         const ParticleMask* only = nullptr);

}  // namespace ejecta
