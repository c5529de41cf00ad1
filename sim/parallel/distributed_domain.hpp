#pragma once
// The distributed half of a Simulation: which particles this rank owns (a Hilbert-curve
// decomposition, rebalanced by measured cost), the halos it borrows from other ranks, and the
// gathers its outputs need. With one rank every operation is a no-op or the identity, and the
// one-rank code path is the serial one, bit for bit (docs/parallel.md).
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "sim/parallel/communicator.hpp"
#include "sim/parallel/decomposition.hpp"
#include "sim/parallel/halo_exchange.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

struct DecompositionOptions {
  // New splitters when the most loaded rank's cost exceeds the mean by this fraction.
  double rebalanceImbalance = 0.1;
};

// Counters of the decomposition, for the summary and the scaling benchmark.
struct DomainStats {
  long rebalances = 0;          // times the splitters were recomputed
  std::size_t migrated = 0;     // particles this rank sent to another owner, all told
  double lastImbalance = 0.0;   // at the last check (max / mean - 1)
  std::size_t haloReceived = 0; // halo particles at the last build
  std::size_t haloSent = 0;
  // Wall time in the exchanges (waiting for slower ranks included) and in the decomposition.
  double haloSeconds = 0.0;
  double rebalanceSeconds = 0.0;
};

class DistributedDomain {
 public:
  DistributedDomain(std::shared_ptr<const Communicator> comm, int dimension,
                    DecompositionOptions options = {});
  const Communicator& comm() const { return *comm_; }
  std::shared_ptr<const Communicator> shared() const { return comm_; }
  bool distributed() const { return comm_->size() > 1; }

  // Keeps this rank's share of a decomposition weighted by `cost` (a collective; equal weights
  // when not given), 
  // from a set every rank holds in full (a restart's snapshot, a scene built whole) or from
  // each rank's slice of the build (buildParticles with ranks). Which of the two it is, the
  // ranks tell by comparing their counts and first and last ids: a whole set is the same on
  // every rank, slices are not.
  using CostFunction = std::function<std::vector<std::uint64_t>(const ParticleSet&)>;
  void keepShare(ParticleSet& p, const CostFunction& cost = {});
  // Sends particles that left this rank's key range to their owners, after new splitters when
  // the cost is out of balance or a particle left the decomposition's box (a collective).
  // `cost[i]` is real particle i's measured work.
  void rebalance(ParticleSet& p, std::span<const std::uint64_t> cost);

  // The halo exchange (sim/parallel/halo_exchange.hpp), timed into stats().
  void buildHalos(ParticleSet& p, double supportFactor);
  // The refresh in two halves (HaloExchange::startRefresh), timed: the time stats() shows is
  // what the overlap did not hide.
  std::unique_ptr<Communicator::PendingExchange> startHaloRefresh(const ParticleSet& p) const;
  void finishHaloRefresh(ParticleSet& p, Communicator::PendingExchange& pending) const;
  void refreshHaloArray(std::vector<double>& values, int stride) const;
  HaloExchange& halos() { return halos_; }
  const HaloExchange& halos() const { return halos_; }

  // Every rank's real particles at rank 0, in id order (a collective; empty elsewhere). The
  // registry (fields, groups) is this rank's.
  ParticleSet gatherToRoot(const ParticleSet& p) const;
  // The real particles within `reach(i)` of any of `points`, from every rank, at rank 0 in
  // id order (a collective): what gauges read.
  ParticleSet gatherNear(const ParticleSet& p, std::span<const std::array<double, 3>> points,
                         double supportFactor) const;
  // This rank's real particles `indices` and every other rank's it names, at rank 0 in id
  // order (a collective; empty elsewhere).
  ParticleSet gatherIndices(const ParticleSet& p, std::span<const std::size_t> indices) const;
  std::uint64_t totalParticles(const ParticleSet& p) const { return comm_->sum(p.numReal); }
  const DomainStats& stats() const { return stats_; }

 private:
  void decompose(ParticleSet& p, std::span<const std::uint64_t> cost);
  // Migrates every real particle to the owner of its key under the current splitters.
  void sendToOwners(ParticleSet& p, std::span<const std::uint64_t> keys);

  std::shared_ptr<const Communicator> comm_;
  int dimension_;
  DecompositionOptions options_;
  Decomposition decomposition_;
  HaloExchange halos_;
  mutable DomainStats stats_;
};

}  // namespace ejecta
