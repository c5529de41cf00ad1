#include "sim/run/packages/fracture_package.hpp"

#include "sim/run/leapfrog.hpp"

namespace ejecta {

void FracturePackage::registerFields(ParticleSet& p) {
  if (!p.hasFracture()) p.enableFracture();
}

void FracturePackage::distributeFlaws(const ParticleSet& initial, const MaterialTable& materials) {
  flaws_ = distributeMaterialFlaws(initial, materials);
  flawsReady_ = true;
}

void FracturePackage::limitKicks(Leapfrog& leapfrog, const PackageContext& c) {
  // The crack's cap comes from the state its kick starts from (sim/run/leapfrog.hpp).
  const MaterialTable* materials = &c.materials;
  const int dimension = c.dimension;
  leapfrog.setCaps("crack", [this, materials, dimension](const ParticleSet& p) {
    return crackCaps(p, *materials, flaws_, dimension);
  });
}

void FracturePackage::updateState(ParticleSet& p, const PackageContext& c) {
  applyDamageToTension(p, c.active);
}

void FracturePackage::evaluateDerivatives(ParticleSet& p, const PackageContext& c) {
  computeCrackGrowth(p, c.materials, flaws_, c.dimension, c.active);
}

void FracturePackage::finalize(ParticleSet& p, const PackageContext& c) {
  lastFailures_ = applyFailure(p, c.materials, c.active);
}

double FracturePackage::timestep(const ParticleSet& p, const PackageContext& c) const {
  // No Grady-Kipp crack fraction may grow by more than maxCrackIncrement in a step, so that the
  // stress a cracking particle sheds reaches its neighbours while it cracks.
  return crackGrowthTimestep(p, c.materials);
}

void FracturePackage::particleTimesteps(const ParticleSet& p, const PackageContext& c,
                                        std::span<const std::size_t> which,
                                        std::span<double> dt) const {
  crackGrowthTimesteps(p, c.materials, which, dt);
}

}  // namespace ejecta
