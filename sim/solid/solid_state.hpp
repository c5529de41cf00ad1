#pragma once
// Per-particle updates of the solid state that sit outside the pair loops: temperature, the
// damage reduction of tension, plasticity (radial return), Grady-Kipp crack growth rates, and
// failure by principal stress or erosion. Each loops over the real particles once.
#include <cstdint>
#include <span>
#include <vector>

#include "sim/solid/materials.hpp"
#include "sim/solid/weibull_flaws.hpp"
#include "sim/state/particle_mask.hpp"
#include "sim/state/particles.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

// Flaws of every particle that can fracture by Grady-Kipp, found by particle id.
struct FlawSet {
  std::vector<FlawTable> tables;          // one per material (empty for other materials)
  std::vector<std::int32_t> tableOfId;    // by particle id: material whose table holds it, or -1
  std::vector<std::uint32_t> rowOfId;     // by particle id: row in that table
  bool empty() const { return tables.empty(); }
};

// Distributes the flaws of each Grady-Kipp material over its particles in `initial` (the
// particles as built at t = 0, so a restarted run draws the same flaws): volume m / rho each,
// seeded by the material's fracture seed and index.
FlawSet distributeMaterialFlaws(const ParticleSet& initial, const MaterialTable& materials);

// After the equation of state, per real particle:
// the temperature from u (each material's thermal model);
void applyTemperature(ParticleSet& p, const MaterialTable& materials,
                      const ParticleMask* only = nullptr);
// damaged particles' tension scaled by (1 - D) (no-op without fracture fields);
void applyDamageToTension(ParticleSet& p, const ParticleMask* only = nullptr);
// for solids the sound speed raised to the longitudinal speed sqrt(c^2 + 4G/(3 rho)), the
// signal speed the time step and the viscosity must respect.
void applySolidSoundSpeed(ParticleSet& p, const MaterialTable& materials,
                          const ParticleMask* only = nullptr);

// Radial return of the stored deviatoric stress S to each material's flow stress Y. The force
// uses (1 - D) S, so the effective stress then sits on the damaged yield surface (1 - D) Y;
// for the Collins model Y = Y(P, D) already holds the damage and the force uses S itself
// (StrengthModel::yieldCarriesDamage), and the whole increment counts as plastic strain. With
// `accumulatePlasticStrain` the equivalent plastic strain grows by (1 - D) times the returned
// increment: the intact volume fraction yields, the cracked fraction D slides on its cracks and
// adds none, so fully damaged material (no shear) gains no plastic strain (docs/materials.md).
void applyPlasticity(ParticleSet& p, const MaterialTable& materials, bool accumulatePlasticStrain,
                     const ParticleMask* only = nullptr);

// Grady-Kipp rates d(crack)/dt of the real particles (0 for other materials).
void computeCrackGrowth(ParticleSet& p, const MaterialTable& materials, const FlawSet& flaws,
                        int dimension, const ParticleMask* only = nullptr);

// Grady-Kipp caps (n_act / n_total)^(1/3) of the crack fraction of every real particle whose
// crack grows (dcrack_dt > 0), from the flaws its present state activates; 1 for the others.
// The time integration bounds each update of the crack fraction by these (advanceCrack).
std::vector<double> crackCaps(const ParticleSet& p, const MaterialTable& materials,
                              const FlawSet& flaws, int dimension);

// The longest time step over which no real particle's crack fraction grows, at its present
// rate, by more than its material's maxCrackIncrement (infinity when no crack grows).
double crackGrowthTimestep(const ParticleSet& p, const MaterialTable& materials);
// The same limit per particle: lowers dt[k] for particle which[k] (individual time steps).
void crackGrowthTimesteps(const ParticleSet& p, const MaterialTable& materials,
                          std::span<const std::size_t> which, std::span<double> dt);

// Principal-stress failure and erosion: sets the damage of failing particles to 1 (and their
// tension to 0). Returns the number of particles that failed now.
std::size_t applyFailure(ParticleSet& p, const MaterialTable& materials,
                         const ParticleMask* only = nullptr);

// The full effective stress tensor of particle i: -P I + (1 - D) S (tension positive), or
// -P I + S when the material's yield surface carries the damage (Collins). Inline: the force
// pass builds it for every solid particle, twice with artificial stress.
inline SymTensor effectiveStress(const ParticleSet& p, std::size_t i, bool yieldCarriesDamage) {
  SymTensor sigma;
  const double intact = yieldCarriesDamage ? 1.0 : 1.0 - p.damage(i);
  for (int c = 0; c < p.stressComponents(); ++c) sigma[c] = intact * p.stress[c][i];
  for (int c = 0; c < 3; ++c) sigma[c] -= p.P[i];
  return sigma;
}
inline SymTensor effectiveStress(const ParticleSet& p, std::size_t i) {
  return effectiveStress(p, i, false);
}

}  // namespace ejecta
