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
    dt[k] = std::min(courantTimestep(sph, p_.h[i], p_.cs[i], p_.divv[i]),
                     forceTimestep(sph, p_.h[i], a2));
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

void Simulation::startBlock(double limit) {
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
  if (!bins_->beginSteps(p_, leapfrog_, all, {}))
    checkHealth(0.0);  // a limit finer than the finest bin: below dt_min, with the diagnosis
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
  if (!bins_->beginSteps(p_, leapfrog_, ended, floor)) checkHealth(0.0);
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
  for (std::size_t s = 0; s < p_.numReal; ++s)
    if (wanted[s] >= 0) bins_->wake(p_, s, wanted[s]);
}

void Simulation::stepIndividually(double limit) {
  ++stateVersion_;
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
  const TimeBins::Tick next = bins_->nextEnd(p_);
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
    setSmoothingFromDensity(p_, ws_);

  evaluateDerivatives(&active);

  bins_->finishSteps(p_, leapfrog_, active, dim);
  evaluateEquationOfState();
  for (const auto& package : packages_) package->finalize(p_, packageContext(&activeMask_));
  time_ = stateTime_;
  ++step_;
  lastDt_ = time_ - before;
  const double smallest = ownTimesteps(active);
  checkHealth(smallest);
  if (bins_->synchronised()) {
    // Every particle is at the block's end: what a restart from here needs of their last
    // evaluation goes into the stored fields.
    bins_->keepEvaluation(p_, ws_.velocityGradient);
    dtNext_ = smallest;
  } else {
    rebin(active);
    dtNext_ = bins_->timeAt(bins_->nextEnd(p_)) - time_;
  }
}

}  // namespace ejecta
