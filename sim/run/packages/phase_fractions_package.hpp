#pragma once
// Phase fractions: the mass fractions molten and vaporised of the materials with phase changes
// (sim/solid/thermal.hpp), from each evaluated state's specific energy. Fields `melt_fraction`
// (liquid or vapour) and `vapour_fraction`, in the snapshots and on the grids; nothing evolves.
#include "sim/run/physics_package.hpp"

namespace ejecta {

class PhaseFractionsPackage : public PhysicsPackage {
 public:
  static constexpr const char* kMeltFraction = "melt_fraction";
  static constexpr const char* kVapourFraction = "vapour_fraction";

  std::string name() const override { return "phase_fractions"; }
  void registerFields(ParticleSet& p) override;
  void updateState(ParticleSet& p, const PackageContext& c) override;
};

}  // namespace ejecta
