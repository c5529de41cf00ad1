// Simulation's individual time steps (sim/run/time_bins.hpp): one sub-step advances every
// particle to where the next steps end and evaluates only the particles whose step ends there.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "sim/run/simulation.hpp"
#include "sim/run/timestep_criteria.hpp"
#include "sim/sph/density_pass.hpp"
#include "sim/sph/kernel.hpp"

namespace ejecta {

namespace {

constexpr long kSortInterval = 16;  // as global steps: reorder for locality every 16 (sub-)steps

}  // namespace

std::uint64_t Simulation::particleUpdates() const {
  return domain_.comm().sum(static_cast<std::size_t>(bins_ ? bins_->updates() : globalUpdates_));
}

double Simulation::ownTimesteps(const std::vector<std::size_t>& which) {
  const SphOptions& sph = scene_.sph;
  std::vector<double> dt(which.size());
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < which.size(); ++k) {
    const std::size_t i = which[k];
    double a2 = 0.0;
    for (int d = 0; d < 3; ++d) a2 += p_.a[d][i] * p_.a[d][i];
    // An isolated particle keeps its own Courant step here (unlike global steps): on a short
    // bin it costs only its own updates, and on a long one it could fly into a neighbour's
    // kernel in mid-step before the limiter sees it (measured on the case 2 follower's burst:
    // energy error 2.8e-2 against 1.8e-3).
    dt[k] = std::min({courantTimestep(sph, p_.h[i], p_.cs[i], p_.divv[i], closingSpeedOf(i)),
                      conductionTimestepOf(i), forceTimestep(sph, p_.h[i], a2)});
  }
  const PackageContext context = packageContext();
  for (const auto& package : packages_) package->particleTimesteps(p_, context, which, dt);
  std::vector<double>& own = bins_->ownSteps(p_);
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < which.size(); ++k) {
    own[which[k]] = dt[k];
    smallest = std::min(smallest, dt[k]);
  }
  return domain_.comm().minimum(smallest);
}

double Simulation::conductionTimestepOf(std::size_t i) const {
  const bool conducting = scene_.sph.conductivity > 0.0 && i < ws_.conductionSignal.size();
  return conductionTimestep(scene_.sph, p_.h[i], conducting ? ws_.conductionSignal[i] : 0.0);
}

TimeBins::Tick Simulation::nextStepEnd() const {
  // Ticks are integers below 2^53: exact as doubles, so the ranks' minimum is exact too.
  return static_cast<TimeBins::Tick>(
      domain_.comm().minimum(static_cast<double>(bins_->nextEnd(p_))));
}

void Simulation::startBlock(double limit) {
  if (domain_.distributed()) {
    // Every particle is at the block's start: particles move to their ranks (weighted by how
    // often their bins evaluate them), and the results of their last evaluation, stored in
    // their fields at the block's end, come back into the workspace in the new order.
    domain_.rebalance(p_, particleCosts());
    bins_->restoreEvaluation(p_, ws_.velocityGradient);
    ws_.neighbourCount.clear();  // counted again as each particle is evaluated
  }
  // The deposit raises sound speeds by orders of magnitude: every particle's derivatives and own
  // step must come from the state with the energy (as with global steps).
  std::vector<std::size_t> all(p_.numReal);
  std::iota(all.begin(), all.end(), std::size_t{0});
  if (fireDueDeposits()) {
    stateTime_ = time_;
    evaluateDerivatives();
    computeNextTimestep();
    checkHealth(dtNext_);
    ownTimesteps(all);
  }
  const double end = std::min(limit, nextDepositTime());
  if (!(end > time_))
    throw std::logic_error("individual time steps: a block must end after t = " +
                           std::to_string(time_) + " s");
  bins_->registerFields(p_, leapfrog_, scene_.sph.density == DensityMethod::Summation,
                        densityPassSetsSmoothingLength(scene_.sph));
  bins_->beginBlock(time_, end - time_);
  for (const auto& package : packages_) package->limitKicks(leapfrog_, packageContext());
  // A limit finer than the finest bin on any rank: below dt_min, with the diagnosis.
  if (!domain_.comm().allTrue(bins_->beginSteps(p_, leapfrog_, all, {}))) checkHealth(0.0);
}

void Simulation::rebin(const std::vector<std::size_t>& ended) {
  std::vector<double>& bin = bins_->bins(p_);
  std::vector<int> floor(ended.size(), 0);
  if (bins_->limiting()) {
    // No coarser than the limiter allows next to the neighbours' present bins (images and halos
    // carry their source's).
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < ended.size(); ++k) {
      int finest = 0;
      for (std::uint32_t j : ws_.lists.pairs(ended[k]))
        finest = std::max(finest, static_cast<int>(bin[j]));
      floor[k] = bins_->floorFrom(finest);
    }
  }
  if (!domain_.comm().allTrue(bins_->beginSteps(p_, leapfrog_, ended, floor))) {
    evaluateSkipped();  // the diagnosis reads every particle
    checkHealth(0.0);
  }
  if (!bins_->limiting()) return;
  // Wake the neighbours whose step in progress is too long beside the new bins: each takes the
  // finest bin any such neighbour asks of it (a max: the order of the loop does not matter).
  std::vector<int> wanted(p_.numReal, -1);
  for (std::size_t i : ended)
    for (std::uint32_t j : ws_.lists.pairs(i)) {
      std::size_t s = j;
      if (j >= p_.numReal) {
        if (j >= p_.numReal + boundaries_.numBoundaryGhosts()) continue;  // another rank's
        s = p_.ghostSource[j - p_.numReal];
      }
      if (activeMask_[s]) continue;  // it has just begun its own step, within the floor
      const int need = bins_->floorFrom(static_cast<int>(bin[i]));
      if (static_cast<int>(bin[s]) < need) wanted[s] = std::max(wanted[s], need);
    }
  if (domain_.distributed()) wakeFromHalos(wanted);
  for (std::size_t s = 0; s < p_.numReal; ++s)
    if (wanted[s] >= 0) bins_->wake(p_, s, wanted[s]);
}

void Simulation::wakeFromHalos(std::vector<int>& wanted) {
  // The particles of other ranks that began a step here wake this rank's neighbours, as this
  // rank's own do above: each rank sends the new bin of its active particles (-1: inactive) to
  // the ranks that hold them as halos, and looks up, around each such halo, the particles its
  // support reaches or whose support reaches it (the pairs the owner's pair list holds).
  const std::vector<double>& bin = bins_->bins(p_);
  const std::size_t ghosts = boundaries_.numBoundaryGhosts();
  std::vector<double> began(p_.size(), -1.0);
  for (std::size_t i = 0; i < p_.numReal; ++i)
    if (activeMask_[i]) began[i] = bin[i];
  for (std::size_t g = p_.numReal; g < p_.numReal + ghosts; ++g)
    began[g] = began[p_.ghostSource[g - p_.numReal]];  // images sent as halos carry their source's
  domain_.refreshHaloArray(began, 1);
  std::vector<std::uint32_t> found;
  for (std::size_t j = p_.numReal + ghosts; j < p_.size(); ++j) {
    if (began[j] < 0.0) continue;
    const double xj[3] = {p_.x[0][j], p_.x[1][j], p_.x[2][j]};
    const double own = kKernelSupport * p_.h[j];
    // Those within its support, then those whose own support may reach it (a particle may
    // appear twice: the wake takes a maximum).
    found.clear();
    const int d = ws_.dim;
    const double reach = ws_.grid.reachInto(xj);
    if (d == 1) {
      ws_.grid.query<1>(p_, xj, own, found);
      ws_.grid.queryReaching<1>(xj, reach, found);
    } else if (d == 2) {
      ws_.grid.query<2>(p_, xj, own, found);
      ws_.grid.queryReaching<2>(xj, reach, found);
    } else {
      ws_.grid.query<3>(p_, xj, own, found);
      ws_.grid.queryReaching<3>(xj, reach, found);
    }
    const int need = bins_->floorFrom(static_cast<int>(began[j]));
    for (std::uint32_t k : found) {
      if (k >= p_.numReal + ghosts) continue;  // another rank's
      double r2 = 0.0;
      for (int a = 0; a < d; ++a) r2 += (p_.x[a][k] - xj[a]) * (p_.x[a][k] - xj[a]);
      const double theirs = kKernelSupport * p_.h[k];
      if (!(r2 < own * own || r2 < theirs * theirs)) continue;
      const std::size_t s = k < p_.numReal ? k : p_.ghostSource[k - p_.numReal];
      if (activeMask_[s]) continue;
      if (static_cast<int>(bin[s]) < need) wanted[s] = std::max(wanted[s], need);
    }
  }
}

void Simulation::stepIndividually(double limit) {
  ++stateVersion_;
  // Nothing is evaluated at the state this sub-step goes to until its evaluation marks what it
  // read (evaluateSkipped, after a failure on the way, evaluates every particle).
  readMask_.assign(p_.numReal, 0);
  if (bins_->synchronised()) {
    startBlock(limit);
  } else if (limit < bins_->timeAt(TimeBins::kBlockTicks) * (1.0 - 1e-12)) {
    std::ostringstream s;
    s.precision(17);
    s << "individual time steps: the step limit " << limit << " s falls inside the block that "
      << "ends at " << bins_->timeAt(TimeBins::kBlockTicks) << " s (a block ends where the limit "
      << "stood when it began)";
    throw std::logic_error(s.str());
  }
  if (step_ % kSortInterval == 0) sortForLocality();
  for (const auto& package : packages_) package->limitKicks(leapfrog_, packageContext());
  const int dim = ws_.dim;
  const double before = time_;

  // Every particle to the next end of a step: positions drifted, fields predicted, and the
  // first half kick of those whose step ends there (the active ones).
  const TimeBins::Tick next = nextStepEnd();
  std::vector<std::size_t> active = bins_->advanceTo(p_, leapfrog_, next, dim);
  activeMask_.assign(p_.numReal, 0);
  for (std::size_t i : active) activeMask_[i] = 1;
  stateTime_ = bins_->timeAt(next);
  for (const auto& package : packages_) package->afterDrift(p_, packageContext());
  {
    // A reflected particle's start velocity and rate flip with it, so its prediction (and the
    // half-step velocity it drifts by) stay mirrored.
    const Field& v0 = *p_.field("velocity:start");
    boundaries_.confine(p_, [&](int d, std::size_t i) {
      std::vector<double>& start = p_.column(v0, d);
      start[i] = -start[i];
      p_.a[static_cast<std::size_t>(d)][i] = -p_.a[static_cast<std::size_t>(d)][i];
    });
  }
  const SphOptions& sph = scene_.sph;
  if (sph.density == DensityMethod::Continuity && sph.smoothingLength == SmoothingLengthMethod::Neighbours)
    smoothingLengthFromDensity();

  evaluateDerivatives(&active);

  bins_->finishSteps(p_, leapfrog_, active, dim);
  // The others' state is that of this sub-step's evaluation already, or (not read by it) of the
  // last one that read them: evaluateSkipped brings them up to date for a reader of all.
  evaluateEquationOfState(&activeMask_);
  for (const auto& package : packages_) package->finalize(p_, packageContext(&activeMask_));
  time_ = stateTime_;
  ++step_;
  lastDt_ = time_ - before;
  const double smallest = ownTimesteps(active);
  // Between synchronisation points only the particles that stepped have a new state (the
  // others' are predictions from states already checked); at a block's end, all of them.
  checkHealth(smallest, bins_->synchronised() ? nullptr : &active);
  if (bins_->synchronised()) {
    // Every particle is at the block's end: what a restart from here needs of their last
    // evaluation goes into the stored fields.
    bins_->keepEvaluation(p_, ws_.velocityGradient);
    dtNext_ = smallest;
  } else {
    rebin(active);
    dtNext_ = bins_->timeAt(nextStepEnd()) - time_;
  }
}

}  // namespace ejecta
