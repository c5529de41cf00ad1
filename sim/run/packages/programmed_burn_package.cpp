#include "sim/run/packages/programmed_burn_package.hpp"

#include <stdexcept>

namespace ejecta {

void ProgrammedBurnPackage::registerFields(ParticleSet& p) {
  if (!p.hasBurn())  // the Simulation adds the package only where they are: a misuse
    throw std::logic_error("programmed burn needs the particles' lighting times (build them with "
                           "buildParticles)");
}

void ProgrammedBurnPackage::updateState(ParticleSet& p, const PackageContext& c) {
  applyProgrammedBurn(p, burn_, eta_, c.time, c.active);
}

void ProgrammedBurnPackage::markEvaluatedEverySubStep(const ParticleSet& p, ParticleMask& evaluated) const {
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.burnFraction[i] < 1.0) evaluated[i] = 1;  // an inert material's fraction is 1 from the start
}

}  // namespace ejecta
