#include "sim/run/packages/strength_package.hpp"

#include "sim/solid/solid_state.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

void StrengthPackage::registerFields(ParticleSet& p) {
  if (p.stressComponents() == 0) p.enableStrength(stressComponentCount(dimension_));
}

void StrengthPackage::afterDrift(ParticleSet& p, const PackageContext& c) {
  if (!returnAfterEquationOfState_) applyPlasticity(p, c.materials, false);
}

void StrengthPackage::afterEquationOfState(ParticleSet& p, const PackageContext& c) {
  if (returnAfterEquationOfState_) applyPlasticity(p, c.materials, false, c.active);
}

void StrengthPackage::updateState(ParticleSet& p, const PackageContext& c) {
  applySolidSoundSpeed(p, c.materials, c.active);
}

void StrengthPackage::finalize(ParticleSet& p, const PackageContext& c) {
  applyPlasticity(p, c.materials, true, c.active);
}

}  // namespace ejecta
