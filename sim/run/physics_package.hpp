#pragma once
// A physics package: a term of the equations that owns its per-particle state, its rates and its
// vote on the time step (in the spirit of Spheral's Physics: registerState / evaluateDerivatives /
// dt). A package declares its fields once (sim/state/field_spec.hpp); the leapfrog then advances
// them, snapshots and restarts carry them and the XDMF lists them with no other change
// (docs/design.md). Called per particle set, never per pair: the pair loops stay fused.
#include <limits>
#include <string>

#include "sim/state/particles.hpp"

namespace ejecta {

class PhysicsPackage {
 public:
  virtual ~PhysicsPackage() = default;
  virtual std::string name() const = 0;
  // Declares the package's fields on the particles (ParticleSet::declare). Called once when the
  // package joins a Simulation; on a restart the values read back from the snapshot are kept.
  virtual void registerFields(ParticleSet& p) const = 0;
  // The rates of the package's evolved fields for the real particles, after the pair passes, at
  // time `t` of the state they see.
  virtual void evaluateDerivatives(ParticleSet& p, double t) const = 0;
  // The longest step the package allows from the present state (infinity: no limit).
  virtual double timestep(const ParticleSet&) const { return std::numeric_limits<double>::infinity(); }
};

}  // namespace ejecta
