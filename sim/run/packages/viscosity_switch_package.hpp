#pragma once
// The Morris & Monaghan (1997) viscosity switch: alpha per particle, kept in [alpha_min, alpha]
// by the leapfrog's clamp. Its source term is computed in the force pass
// (sim/sph/terms/monaghan_viscosity.hpp: viscositySwitchRate) and the pair viscosity reads it;
// this package owns its state.
#include "sim/run/physics_package.hpp"
#include "sim/sph/sph_options.hpp"

namespace ejecta {

class ViscositySwitchPackage : public PhysicsPackage {
 public:
  explicit ViscositySwitchPackage(const SphOptions& sph) : sph_(sph) {}
  std::string name() const override { return "viscosity_switch"; }
  // alpha_min, or alpha_max in explosive particles (initialiseViscosityAlpha); a restart keeps
  // its snapshot's alpha.
  void registerFields(ParticleSet& p) override;

 private:
  SphOptions sph_;
};

}  // namespace ejecta
