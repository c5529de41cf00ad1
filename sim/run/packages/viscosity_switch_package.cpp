#include "sim/run/packages/viscosity_switch_package.hpp"

#include "sim/sph/hydro_force.hpp"

namespace ejecta {

void ViscositySwitchPackage::registerFields(ParticleSet& p) {
  initialiseViscosityAlpha(p, sph_);
  p.setClampRange("viscosity_alpha", sph_.alphaMin, sph_.alpha);
}

}  // namespace ejecta
