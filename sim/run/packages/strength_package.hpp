#pragma once
// Strength: the deviatoric stress of the materials that have it (sim/solid/strength.hpp). Its
// rate (the Jaumann rate of the velocity gradient) comes from the force pass
// (sim/sph/terms/stress_divergence.hpp); here the solid's longitudinal sound speed after each
// equation of state, and the radial return to the flow stress after the drift (predicted state)
// and at the end of the step (where the plastic strain accumulates).
#include "sim/run/physics_package.hpp"

namespace ejecta {

class StrengthPackage : public PhysicsPackage {
 public:
  std::string name() const override { return "strength"; }
  void registerFields(ParticleSet& p) override;
  void afterDrift(ParticleSet& p, const PackageContext& c) override;
  void updateState(ParticleSet& p, const PackageContext& c) override;
  void finalize(ParticleSet& p, const PackageContext& c) override;

  explicit StrengthPackage(int dimension) : dimension_(dimension) {}

 private:
  int dimension_;
};

}  // namespace ejecta
