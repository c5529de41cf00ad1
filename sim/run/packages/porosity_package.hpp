#pragma once
// Porosity: the distention alpha of the porous materials, by P-alpha (sim/solid/porosity.hpp) or
// epsilon-alpha (sim/solid/strain_porosity.hpp). After each equation of state it replaces a
// porous particle's pressure and sound speed by the porous material's, P = P_s(alpha rho, u) /
// alpha, and it votes on the time step so that alpha moves by at most max_distention_change a
// step. It joins first, so the packages after it (burn, strength, fracture) scale the porous
// pressure and sound speed as they would a solid's.
// - P-alpha: after the pair passes it gives alpha's rate from the rates of density and energy;
//   at the end of a step a state the integration left above the crush curve returns to it.
// - epsilon-alpha: alpha is a function of the volumetric strain (evolved from the bulk's
//   dV/V rate) and of the most compressive strain reached (lowered to the strain at the end of
//   each step), evaluated before each equation of state: no rate of its own, no return. The
//   shared distention field is kicked with rate 0 for these particles (the integrator may set it
//   back to its step-start value); the equation of state that follows every kick recomputes it
//   before anything reads it.
#include <cstddef>
#include <vector>

#include "sim/run/physics_package.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/solid/strain_porosity.hpp"
#include "sim/sph/sph_options.hpp"

namespace ejecta {

class PorosityPackage : public PhysicsPackage {
 public:
  static constexpr const char* kDistention = kDistentionField;
  static constexpr const char* kDistentionRate = "distention_rate";
  // epsilon-alpha's volumetric strain eps = ln(V/V0) (less the thermal part), its rate, and the
  // most compressive strain reached, eps_min.
  static constexpr const char* kStrain = "volumetric_strain";
  static constexpr const char* kStrainRate = "volumetric_strain_rate";
  static constexpr const char* kLeastStrain = "compaction_strain";

  PorosityPackage(const MaterialTable& materials, DensityMethod density);

  std::string name() const override { return "porosity"; }
  void registerFields(ParticleSet& p) override;
  void updateState(ParticleSet& p, const PackageContext& c) override;
  void evaluateDerivatives(ParticleSet& p, const PackageContext& c) override;
  void finalize(ParticleSet& p, const PackageContext& c) override;
  double timestep(const ParticleSet& p, const PackageContext& c) const override;
  void particleTimesteps(const ParticleSet& p, const PackageContext& c,
                         std::span<const std::size_t> which, std::span<double> dt) const override;

 private:
  // The columns the step vote reads, looked up once per vote.
  struct StepColumns {
    const double* distentionRate = nullptr;
    const double* strain = nullptr;
    const double* leastStrain = nullptr;
    const double* strainRate = nullptr;
  };
  StepColumns stepColumns(const ParticleSet& p) const;
  double particleTimestep(const ParticleSet& p, const PackageContext& c, const StepColumns& columns,
                          std::size_t i) const;

  DensityMethod density_;
  // Each material's model of its kind, or null (none, or the other kind).
  std::vector<const PalphaModel*> palpha_;
  std::vector<const EpsilonAlphaModel*> epsilonAlpha_;
  bool anyEpsilonAlpha_ = false;
  std::vector<double> initialDistention_;  // alpha_0 by material (1: not porous)
  double largestInitialDistention_ = 1.0;
  // Scratch of updateState: each porous material's selected particles and their matrix state.
  std::vector<std::size_t> members_;
  std::vector<double> matrixDensity_, matrixPressure_, matrixSoundSpeed_;
};

}  // namespace ejecta
