#pragma once
// Simulation: the particles, the materials and the physics terms a scene asks for, advanced in
// time by kick-drift-kick leapfrog (the seed's eq. 1.9 in its synchronised form):
//   v^(n+1/2) = v^n + a^n dt/2,  x^(n+1) = x^n + v^(n+1/2) dt,  v^(n+1) = v^(n+1/2) + a^(n+1) dt/2
// and likewise for u (and rho with continuity density, h with the seed's dh/dt). Derivatives at
// n+1 use velocities and energies predicted to n+1. Every step: neighbours -> density pass ->
// equation of state -> force pass; then the time-step criteria and a health check.
#include <array>
#include <functional>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/parallel/distributed_domain.hpp"
#include "sim/sph/boundaries.hpp"
#include "sim/state/conservation.hpp"
#include "sim/sph/hydro_workspace.hpp"
#include "sim/run/leapfrog.hpp"
#include "sim/run/time_bins.hpp"
#include "sim/run/physics_package.hpp"
#include "sim/run/packages/fracture_package.hpp"
#include "sim/run/packages/smoothing_length_cap_package.hpp"
#include "sim/solid/materials.hpp"
#include "sim/state/particles.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta {

// A bad numerical state: the message names the step, time, particle and its state.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A delayed energy deposit (EnergyDepositSpec::time > 0) that has fired: when, where, and the
// energy ledger's reference just before it (the target's energy "just before the deposit").
struct DepositFiring {
  std::size_t deposit = 0;                 // index into Scene::deposits
  double time = 0.0;                       // the start of the step it fired at [s]
  long step = 0;                           // steps taken before it fired
  std::array<double, 3> point{};           // centroid of the deposited energy [m]
  std::vector<double> kineticBefore;       // per material, just before it [J]
  std::vector<double> internalBefore;      // per material, just before it [J]
};

class Simulation {
 public:
  // `particles` are the whole scene's on every rank; a distributed run (`ranks` with more than
  // one rank; nullptr: one) keeps this rank's share of them (sim/parallel/distributed_domain.hpp).
  Simulation(Scene scene, ParticleSet particles, MaterialTable materials, int numThreads,
             std::shared_ptr<const Communicator> ranks = nullptr);
  // Its packages hold state (the flaws, the leapfrog's caps): a copy would share them.
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;
  Simulation(Simulation&&) = default;
  Simulation& operator=(Simulation&&) = default;

  // Computes the derivatives of the current state and the next time step. Call once before the
  // first step() of a new run; a restarted run instead calls resume() with stored values.
  void initialise();
  void resume(double time, long step, double dtNext);

  // Grady-Kipp flaws are drawn from the particles as built at t = 0 (their volumes m/rho). A new
  // run uses its own particles (initialise() does this); a restarted run must pass the scene's
  // freshly built particles so it draws the same flaws.
  void distributeFlaws(const ParticleSet& initial);
  // Adds a physics package (sim/run/physics_package.hpp) before the first step or resume():
  // its fields are declared on the particles now.
  // The scene's own packages (programmed burn, strength, fracture, the viscosity switch) join
  // in the constructor, in that order; others join after them.
  void addPackage(std::shared_ptr<PhysicsPackage> package);
  // Particles that failed (principal stress or erosion) in the last step.
  std::size_t lastFailures() const { return fracture_ ? fracture_->lastFailures() : 0; }

  // Individual steps: advances one sub-step, to where the next particles' steps end. When every
  // particle is synchronised a block begins that ends at min(limit, the next delayed deposit); a
  // smaller limit before the block ends is an error (std::logic_error): the run's outputs are its
  // limits, and each block ends on one.
  // Global steps: advances one step of min(next time step, limit - time, next delayed deposit - time). A
  // delayed deposit due at the step's start (time >= its time) fires first: its energy is added,
  // the derivatives and the time step are recomputed from the new state, and the step takes that
  // time step. Throws SimulationError on a bad state (the particles then hold the offending
  // state, for a last snapshot), SceneError for a delayed deposit whose region is empty.
  void step(double limit);

  // The delayed deposits fired so far, in order, and the energy they added [J].
  const std::vector<DepositFiring>& depositFirings() const { return firings_; }
  double delayedEnergyAdded() const;
  // A restarted run: the deposits its snapshot had already fired (they do not fire again).
  void restoreDepositFirings(std::vector<DepositFiring> firings) { firings_ = std::move(firings); }

  double time() const { return time_; }
  long stepCount() const { return step_; }
  double dtNext() const { return dtNext_; }
  double lastDt() const { return lastDt_; }
  // Individual time steps ([time] stepping = "individual"): whether every particle is at time()
  // (always with global steps), and the particle-steps taken so far (with global steps, the
  // particles times the steps).
  bool individualSteps() const { return bins_.has_value(); }
  bool synchronised() const { return !bins_ || bins_->synchronised(); }
  std::uint64_t particleUpdates() const;
  const Scene& scene() const { return scene_; }
  // This rank's particles (all of them on one rank).
  const ParticleSet& particles() const { return p_; }
  // (Write access may change the state: a later gatheredParticles() gathers afresh.)
  ParticleSet& particles() {
    ++stateVersion_;
    return p_;
  }
  const MaterialTable& materials() const { return materials_; }
  // Totals over every rank's particles, summed in rank order (collectives, as is every member
  // below that reads all ranks).
  ConservedTotals totals() const;
  std::vector<ConservedTotals> totalsByMaterial() const;
  double meanNeighbours() const;
  std::uint64_t totalParticles() const { return domain_.totalParticles(p_); }

  // The ranks of this run and the decomposition's counters.
  const Communicator& ranks() const { return domain_.comm(); }
  const DistributedDomain& domain() const { return domain_; }
  // Every rank's particles at rank 0, in id order: what outputs drawn from all of them (images,
  // thermal pictures) read. A collective the first time it is called at a state (every rank
  // calls it; later calls before the state changes reuse the gather). Empty on the other ranks;
  // one rank: particles().
  const ParticleSet& gatheredParticles() const;
  // The real particles for which keep(p, i) holds, from every rank, at rank 0 in id order (a
  // collective; empty elsewhere): a few hot ones for a thermal pass rather than all of them.
  // One rank: those of particles(), in its order.
  using ParticleFilter = std::function<bool(const ParticleSet&, std::size_t)>;
  ParticleSet gatherParticlesWhere(const ParticleFilter& keep) const;
  const ParticleSet& particlesNear(std::span<const std::array<double, 3>> points);
  // Individual steps on one rank evaluate the equation of state (and the packages' state
  // updates) only where a sub-step reads it: its active particles, their partners, the
  // particles a gauge reads and those a package marks (markEvaluatedEverySubStep). A reader of
  // every particle between synchronisation points (an evolving thermal pass, a snapshot after an
  // interrupt or a failure) calls this first to bring the others' pressure, sound speed and
  // temperature to the present state. Cheap when nothing was skipped.
  void evaluateSkipped();

 private:
  // Ghosts, halos, the density pass, the equation of state and the force pass; with `active`
  // (individual steps) the passes and the packages' derivatives for those particles only.
  void evaluateDerivatives(const std::vector<std::size_t>* active = nullptr);
  // Pressure, sound speed and temperature from rho and u, then the packages' state updates;
  // `only` (individual time steps): just the particles it selects (every package's
  // updateState must honour PackageContext::active then: the updates are not idempotent).
  void evaluateEquationOfState(const ParticleMask* only = nullptr);
  // The pairs of the force pass: every real particle's, or (individual steps) the active ones'.
  void buildEvaluatedPairs(const std::vector<std::size_t>* active);
  // readMask_: the active particles, their partners (an image's source for the image), the
  // particles whose support reaches a gauge and those a package marks (an explosive still
  // burning).
  void markReadParticles(const std::vector<std::size_t>& active);
  void computeNextTimestep();
  // A particle in no pair (no real, ghost or halo particle within either's kernel) exchanges
  // nothing, so its sound speed sets no step: a fragment flung clear and rarefied under
  // continuity density can get tens of km/s (a solid's 4G/(3 rho) at a hundredth of its
  // density) and would otherwise set every step of the run. Its acceleration still votes (the
  // force criterion). Global steps only: individual steps give it its own short bin
  // (sim/run/individual_steps.cpp).
  bool isolated(std::size_t i) const {
    return i < ws_.lists.pairedParticles() && ws_.lists.pairs(i).size() <= 1;  // itself alone
  }
  // h from the continuity density (SmoothingLengthMethod::Neighbours), held at the caps.
  // Throws where sph.gradients = "iad" (sim/sph/iad_matrix.hpp), sph.volume_elements =
  // "generalised" or sph.dissipation = "riemann" is not built: more than one rank, RZ and
  // individual steps (but for "riemann"), solids, the interface form, continuity density; and
  // combinations of them.
  void refuseUnbuiltSphOptions() const;
  void smoothingLengthFromDensity();
  // sph.h_max_factor's package (null when h is not capped).
  std::shared_ptr<SmoothingLengthCapPackage> hCaps_;
  // Stops the run (SimulationError on every rank) on a bad state or a step below dt_min; `only`:
  // check just those particles (ascending), the others being known good.
  void checkHealth(double dt, const std::vector<std::size_t>* only = nullptr) const;
  // The real particle with the tightest own step limit, the limit and the criterion that set it
  // (Courant, force, conduction or a package's), for checkHealth's dt_min diagnosis.
  struct StepLimit {
    std::size_t particle;
    double dt;
    std::string criterion;
  };
  StepLimit tightestStepLimit() const;
  // Throws SimulationError naming the step, time, `reason` and particle i's state.
  [[noreturn]] void failAt(std::size_t i, const std::string& reason) const;
  std::string failureMessage(std::size_t i, const std::string& reason) const;
  // Stops every rank with the diagnosis of the lowest rank that has one (`local`, empty when
  // this rank found nothing wrong).
  void stopIfAnyRankFailed(const std::string& local) const;
  // The measured work of each real particle, for the decomposition's balance.
  std::vector<std::uint64_t> particleCosts() const;
  void sortForLocality();
  // Fires the delayed deposits due at the current time; true when one fired.
  bool fireDueDeposits();
  // The earliest time of a delayed deposit not yet fired (infinity when none).
  double nextDepositTime() const;
  bool fired(std::size_t deposit) const;
  // What the packages' hooks read besides the particles, at the evaluated state's time.
  PackageContext packageContext(const ParticleMask* active = nullptr) const {
    return {materials_, ws_.dim, stateTime_, active};
  }
  // Individual time steps (sim/run/individual_steps.cpp).
  void stepIndividually(double limit);
  void startBlock(double limit);
  // Each listed particle's own step limit (the hydrodynamic criteria and the packages' votes)
  // into the bins' dt_own; returns the smallest over every rank.
  double ownTimesteps(const std::vector<std::size_t>& which);
  // [time] closing_speed: the fastest closing speed of each evaluated particle's pairs, measured
  // at the end of evaluateDerivatives (closing_), and read by the time-step criteria (0 without
  // the key).
  void measureClosingSpeeds(const std::vector<std::size_t>* active);
  double closingSpeedOf(std::size_t i) const;
  // Individual steps: the artificial conductivity's limit on particle i's step from the
  // evaluation just made (timestep_criteria.hpp; infinity without conductivity). Only then: the
  // workspace's signals are not reordered with the particles (sortForLocality, rebalance).
  double conductionTimestepOf(std::size_t i) const;
  // After the listed particles' steps ended: their new bins (the limiter's floor from their
  // neighbours) and the wake-up of neighbours on too long a step.
  void rebin(const std::vector<std::size_t>& ended);
  // A distributed run: the other ranks' particles that began a step wake this rank's neighbours
  // (raising `wanted`, the bin each particle must take at least).
  void wakeFromHalos(std::vector<int>& wanted);
  // The earliest end of a step in progress on any rank (a collective).
  TimeBins::Tick nextStepEnd() const;

  Scene scene_;
  DistributedDomain domain_;
  ParticleSet p_;
  // Rank 0 of a distributed run: every rank's particles as gathered at state stateVersion_
  // (gatheredParticles), and those near the gauges (particlesNear).
  mutable ParticleSet collected_;
  mutable long collectedVersion_ = -1;
  long stateVersion_ = 0;  // advanced by every change of the state
  ParticleSet near_;
  MaterialTable materials_;
  Boundaries boundaries_;
  HydroWorkspace ws_;
  double time_ = 0.0;
  long step_ = 0;
  double dtNext_ = 0.0;
  double lastDt_ = 0.0;
  double hMin_ = 0.0;
  std::uint32_t maxNeighbours_ = 1u << 30;
  std::vector<std::vector<std::size_t>> materialMembers_;
  // The time of the state the equation of state and the derivatives are evaluated for (the
  // predicted end of the step).
  double stateTime_ = 0.0;
  Leapfrog leapfrog_;  // and its half-step state
  std::optional<TimeBins> bins_;  // individual time steps; empty: global steps
  ParticleMask activeMask_;       // the particles of the present sub-step
  // The particles whose equation of state the last evaluation ran (individual steps on one rank;
  // empty: all of them), until evaluateSkipped.
  ParticleMask readMask_;
  std::vector<std::uint32_t> gaugeCandidates_;  // markReadParticles' scratch
  std::vector<double> closing_;   // measureClosingSpeeds' values [m/s], per real particle
  std::vector<std::shared_ptr<PhysicsPackage>> packages_;
  std::shared_ptr<FracturePackage> fracture_;  // also in packages_; owns the flaws
  std::vector<DepositFiring> firings_;
  std::vector<std::int64_t> bodyFirstIds_;  // for delayed body deposits (bodyFirstIds)
  std::uint64_t globalUpdates_ = 0;         // particle-steps of global steps
};

}  // namespace ejecta
