#pragma once
// A physics package: a term of the equations that owns its per-particle state, its updates
// outside the pair loops and its vote on the time step (in the spirit of Spheral's Physics:
// registerState / evaluateDerivatives / dt / finalize). A package declares its fields once
// (sim/state/field_spec.hpp); the leapfrog then advances them, snapshots and restarts carry
// them and the XDMF lists them with no other change (docs/design.md). Its pair contribution, if
// any, is an inline term of the fused force pass (sim/sph/terms/): the hooks here are called per
// particle set, never per pair.
//
// The life cycle of one step (sim/run/simulation.cpp), each hook over the packages in the order
// they joined:
//   limitKicks -> [leapfrog predict] -> afterDrift -> [pair passes, equation of state]
//   -> updateState -> (individual steps: afterEquationOfState) -> [force pass]
//   -> evaluateDerivatives -> [leapfrog correct, equation of state] -> updateState -> finalize
//   -> timestep
// With individual time steps (sim/run/time_bins.hpp) the same cycle runs at every sub-step on
// the particles' predicted state, the derivative hooks and finalize acting only on
// PackageContext::active. On one rank the equation of state, updateState and
// afterEquationOfState of the predicted state run only for the particles the sub-step reads
// (the active ones, their partners, those a gauge reads, and those a package marks with
// markEvaluatedEverySubStep: PackageContext::active holds them then).
// initialise() and a delayed deposit's firing evaluate a state without stepping: updateState ->
// evaluateDerivatives -> timestep only. A package that keeps state between steps belongs to one
// Simulation.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <string>

#include "sim/solid/materials.hpp"
#include "sim/state/particle_mask.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

class Leapfrog;

// What every hook may read besides the particles.
struct PackageContext {
  const MaterialTable& materials;
  int dimension;  // of the particle positions: 1, 2 (planar and RZ) or 3
  double time;    // of the state the hook sees [s]
  // Individual time steps (sim/run/time_bins.hpp): for evaluateDerivatives and finalize the
  // particles whose step ends at `time`, the only ones they may change (the others keep the
  // rates their step started with, and their state is a prediction); for the state hooks of a
  // predicted state on one rank, the particles the sub-step reads. nullptr: every particle
  // (global steps, and the predicted state's hooks on several ranks).
  const ParticleMask* active = nullptr;
};

class PhysicsPackage {
 public:
  virtual ~PhysicsPackage() = default;
  virtual std::string name() const = 0;
  // Declares the package's fields on the particles (ParticleSet::declare) and gives them their
  // starting values where the particles do not carry them yet. Called when the package joins a
  // Simulation, and by the run on a snapshot's particles to learn their layout, so it must be
  // idempotent: on a restart the values read back from the snapshot are kept.
  virtual void registerFields(ParticleSet& p) = 0;
  // Before each step's first kick: per-particle limits of the package's kicked fields
  // (Leapfrog::setCaps), from the state the step starts from.
  virtual void limitKicks(Leapfrog&, const PackageContext&) {}
  // After the drift, on the predicted state, before the pair passes see it.
  virtual void afterDrift(ParticleSet&, const PackageContext&) {}
  // Individual time steps on one rank: adds to `evaluated` the particles whose state update
  // keeps a history (a running maximum) and so must run at every sub-step, read or not, for the
  // run not to depend on which sub-steps read them (and to match a run on several ranks, which
  // evaluates every particle).
  virtual void markEvaluatedEverySubStep(const ParticleSet&, ParticleMask& /*evaluated*/) const {}
  // Individual time steps: after the equation of state of a sub-step's predicted state and
  // every package's updateState (the pressure complete: burn, damage, distention), for the
  // particles c.active selects (nullptr: all); not for a stored state (initialise, a deposit's
  // firing).
  virtual void afterEquationOfState(ParticleSet&, const PackageContext&) {}
  // After the equation of state of every evaluated state (pressures and sound speeds set) for
  // the particles it evaluated: with individual time steps those c.active selects (the read ones
  // of a predicted state; after the end of a sub-step its active ones), and an update must touch
  // only those (it is not idempotent: it scales P or cs).
  virtual void updateState(ParticleSet&, const PackageContext&) {}
  // The rates of the package's evolved fields for the real particles, after the pair passes.
  virtual void evaluateDerivatives(ParticleSet&, const PackageContext&) {}
  // At the end of a step, on the final state.
  virtual void finalize(ParticleSet&, const PackageContext&) {}
  // The longest step the package allows from the present state (infinity: no limit).
  virtual double timestep(const ParticleSet&, const PackageContext&) const {
    return std::numeric_limits<double>::infinity();
  }
  // Individual time steps: lowers dt[k] to the longest step particle which[k] allows (the
  // particles whose step ends now). The default applies timestep() to each, which is safe but
  // makes every particle wait for the package's most demanding one.
  virtual void particleTimesteps(const ParticleSet& p, const PackageContext& c,
                                 std::span<const std::size_t> which, std::span<double> dt) const {
    (void)which;
    const double limit = timestep(p, c);
    for (double& d : dt) d = std::min(d, limit);
  }
};

}  // namespace ejecta
