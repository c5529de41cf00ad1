#pragma once
// Programmed burn of high explosives (sim/sources/programmed_burn.hpp): each explosive particle's
// lighting time travels with it; after each equation of state the burn fraction scales its
// pressure (Wilkins' programmed burn with the compression criterion).
#include <utility>
#include <vector>

#include "sim/run/physics_package.hpp"
#include "sim/sources/programmed_burn.hpp"

namespace ejecta {

class ProgrammedBurnPackage : public PhysicsPackage {
 public:
  // `eta` is the scene's h/spacing, which sets the width of the burn front.
  ProgrammedBurnPackage(BurnTable burn, double eta) : burn_(std::move(burn)), eta_(eta) {}
  std::string name() const override { return "programmed_burn"; }
  // The lighting times are set when the particles are built (assignLightingTimes): a run whose
  // particles lack them cannot burn, and says so.
  void registerFields(ParticleSet& p) override;
  void updateState(ParticleSet& p, const PackageContext& c) override;
  // The fraction is the largest any evaluation gave (applyProgrammedBurn): an explosive still
  // burning is evaluated at every sub-step.
  void markEvaluatedEverySubStep(const ParticleSet& p, ParticleMask& evaluated) const override;

 private:
  BurnTable burn_;
  double eta_;
};

}  // namespace ejecta
