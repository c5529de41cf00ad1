#pragma once
// Strength: the deviatoric stress of the materials that have it (sim/solid/strength.hpp). Its
// rate (the Jaumann rate of the velocity gradient) comes from the force pass
// (sim/sph/terms/stress_divergence.hpp); here the solid's longitudinal sound speed after each
// equation of state, and the radial return to the flow stress of the predicted state and at the
// end of the step (where the plastic strain accumulates). Global steps return the predicted
// stress after the drift, at the pressure of the last evaluation (the order the golden snapshots
// hold); individual steps after the predicted state's equation of state, at its own pressure,
// so that the return is a function of the present state alone: a particle whose equation of
// state a sub-step skips (not read) needs no return there, and a run on several ranks, which
// evaluates every particle, returns the read ones as one rank does.
#include "sim/run/physics_package.hpp"

namespace ejecta {

class StrengthPackage : public PhysicsPackage {
 public:
  std::string name() const override { return "strength"; }
  void registerFields(ParticleSet& p) override;
  void afterDrift(ParticleSet& p, const PackageContext& c) override;
  void afterEquationOfState(ParticleSet& p, const PackageContext& c) override;
  void updateState(ParticleSet& p, const PackageContext& c) override;
  void finalize(ParticleSet& p, const PackageContext& c) override;

  // `individualSteps`: where the predicted stress is returned (above).
  StrengthPackage(int dimension, bool individualSteps)
      : dimension_(dimension), returnAfterEquationOfState_(individualSteps) {}

 private:
  int dimension_;
  bool returnAfterEquationOfState_;
};

}  // namespace ejecta
