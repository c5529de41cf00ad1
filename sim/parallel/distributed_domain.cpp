#include "sim/parallel/distributed_domain.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>

#include "sim/parallel/particle_packing.hpp"

namespace ejecta {

namespace {

// Adds the wall time of its own life to `total`.
class Stopwatch {
 public:
  explicit Stopwatch(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~Stopwatch() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace

DistributedDomain::DistributedDomain(std::shared_ptr<const Communicator> comm, int dimension,
                                     DecompositionOptions options)
    : comm_(comm ? std::move(comm) : std::make_shared<SerialCommunicator>()),
      dimension_(dimension),
      options_(options) {}

void DistributedDomain::keepShare(ParticleSet& p, const CostFunction& cost) {
  if (!distributed()) return;
  const Stopwatch watch(stats_.rebalanceSeconds);
  p.clearGhosts();
  std::vector<double> lo{static_cast<double>(p.numReal), p.numReal ? static_cast<double>(p.id.front()) : -1.0,
                         p.numReal ? static_cast<double>(p.id[p.numReal - 1]) : -1.0};
  std::vector<double> hi = lo;
  comm_->minInPlace(lo);
  comm_->maxInPlace(hi);
  auto costs = [&] { return cost ? cost(p) : std::vector<std::uint64_t>(p.numReal, 1); };
  if (lo != hi) {  // slices already: lay the curve over them
    decompose(p, costs());
    return;
  }
  // Every rank holds the same particles: each keeps a contiguous slice of them first, so the
  // decomposition's collectives see every particle once.
  const std::size_t n = p.numReal, ranks = static_cast<std::size_t>(comm_->size());
  const std::size_t r = static_cast<std::size_t>(comm_->rank());
  const std::size_t begin = n * r / ranks, end = n * (r + 1) / ranks;
  std::vector<std::size_t> slice(end - begin);
  std::iota(slice.begin(), slice.end(), begin);
  p.permute(slice);
  p.numReal = slice.size();
  decompose(p, costs());
}

void DistributedDomain::decompose(ParticleSet& p, std::span<const std::uint64_t> cost) {
  decomposition_.dimension = dimension_;
  decomposition_.box = globalParticleBox(p, dimension_, *comm_);
  const std::vector<std::uint64_t> keys = hilbertKeys(p, p.numReal, decomposition_.box, dimension_);
  decomposition_.splitters = balancedSplitters(keys, cost, *comm_);
  ++stats_.rebalances;
  sendToOwners(p, keys);
}

void DistributedDomain::sendToOwners(ParticleSet& p, std::span<const std::uint64_t> keys) {
  std::vector<int> destination(p.numReal);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    destination[i] = decomposition_.owner(keys[i]);
    stats_.migrated += destination[i] != comm_->rank();
  }
  migrateParticles(p, destination, *comm_);
}

void DistributedDomain::rebalance(ParticleSet& p, std::span<const std::uint64_t> cost) {
  if (!distributed()) return;
  const Stopwatch watch(stats_.rebalanceSeconds);
  p.clearGhosts();
  const double localCost = std::accumulate(cost.begin(), cost.end(), 0.0);
  stats_.lastImbalance = loadImbalance(localCost, *comm_);
  // A particle outside the box would get a clamped key: its owner would still be right, but the
  // box no longer describes the particles (large motion), so the curve is laid anew.
  bool inside = true;
  for (int d = 0; d < dimension_ && inside; ++d)
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const std::size_t a = static_cast<std::size_t>(d);
      if (p.x[a][i] < decomposition_.box.lo[a] || p.x[a][i] > decomposition_.box.hi[a]) {
        inside = false;
        break;
      }
    }
  if (decomposition_.empty() || !comm_->allTrue(inside) ||
      stats_.lastImbalance > options_.rebalanceImbalance) {
    decompose(p, cost);
    return;
  }
  sendToOwners(p, hilbertKeys(p, p.numReal, decomposition_.box, dimension_));
}

void DistributedDomain::buildHalos(ParticleSet& p, double supportFactor) {
  const Stopwatch watch(stats_.haloSeconds);
  halos_.build(p, dimension_, supportFactor, *comm_);
  stats_.haloReceived = halos_.received();
  stats_.haloSent = halos_.sent();
}

std::unique_ptr<Communicator::PendingExchange> DistributedDomain::startHaloRefresh(const ParticleSet& p) const {
  const Stopwatch watch(stats_.haloSeconds);
  return halos_.startRefresh(p, *comm_);
}

void DistributedDomain::finishHaloRefresh(ParticleSet& p, Communicator::PendingExchange& pending) const {
  const Stopwatch watch(stats_.haloSeconds);
  halos_.finishRefresh(p, pending);
}

void DistributedDomain::refreshHaloArray(std::vector<double>& values, int stride) const {
  const Stopwatch watch(stats_.haloSeconds);
  halos_.refreshArray(values, stride, *comm_);
}

ParticleSet DistributedDomain::gatherIndices(const ParticleSet& p, std::span<const std::size_t> indices) const {
  const ParticlePacker packer(p, PackedFields::All);
  Bytes mine;
  packer.pack(p, indices, mine);
  const std::vector<Bytes> all = comm_->gatherToRoot(mine);
  ParticleSet out = p.withSameFields();  // the same registry, no values copied
  if (!comm_->isRoot()) return out;
  std::size_t total = 0;
  for (const Bytes& b : all) total += packer.count(b);
  out.resize(total);
  std::size_t at = 0;
  for (const Bytes& b : all) {
    packer.unpack(out, b, at);
    at += packer.count(b);
  }
  out.numReal = total;
  std::vector<std::size_t> order(total);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return out.id[a] < out.id[b]; });
  out.permute(order);
  return out;
}

ParticleSet DistributedDomain::gatherToRoot(const ParticleSet& p) const {
  std::vector<std::size_t> all(p.numReal);
  std::iota(all.begin(), all.end(), std::size_t{0});
  return gatherIndices(p, all);
}

ParticleSet DistributedDomain::gatherNear(const ParticleSet& p, std::span<const std::array<double, 3>> points,
                                          double supportFactor) const {
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double reach = supportFactor * p.h[i];
    for (const auto& q : points) {
      double d2 = 0.0;
      for (int d = 0; d < dimension_; ++d) {
        const double dx = p.x[static_cast<std::size_t>(d)][i] - q[static_cast<std::size_t>(d)];
        d2 += dx * dx;
      }
      if (d2 < reach * reach) {
        near.push_back(i);
        break;
      }
    }
  }
  return gatherIndices(p, near);
}

}  // namespace ejecta
