#pragma once
// Porosity: the distention alpha of the porous materials (the P-alpha model,
// sim/solid/porosity.hpp). After each equation of state it replaces a porous particle's pressure
// and sound speed by the porous material's, P = P_s(alpha rho, u) / alpha; after the pair
// passes it gives alpha's rate from the rates of density and energy; at the end of a step a
// particle loaded past Ps is fully compacted; and it votes on the time step so that alpha moves
// by at most max_distention_change a step. It joins first, so the packages after it (burn,
// strength, fracture) scale the porous pressure and sound speed as they would a solid's.
#include <cstddef>
#include <vector>

#include "sim/run/physics_package.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/sph/sph_options.hpp"

namespace ejecta {

class PorosityPackage : public PhysicsPackage {
 public:
  static constexpr const char* kDistention = kDistentionField;
  static constexpr const char* kDistentionRate = "distention_rate";

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
  double particleTimestep(const ParticleSet& p, const PackageContext& c, std::size_t i) const;

  DensityMethod density_;
  std::vector<double> initialDistention_;  // alpha_0 by material (1: not porous)
  double largestInitialDistention_ = 1.0;
  // Scratch of updateState: each porous material's selected particles and their matrix state.
  std::vector<std::size_t> members_;
  std::vector<double> matrixDensity_, matrixPressure_, matrixSoundSpeed_;
};

}  // namespace ejecta
