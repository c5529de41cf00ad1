#include "sim/parallel/decomposition.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "sim/parallel/particle_packing.hpp"

namespace ejecta {

int Decomposition::owner(std::uint64_t key) const {
  // splitters[0] = 0 and splitters.back() = the largest key: the owner is the last r with
  // splitters[r] <= key.
  const auto it = std::upper_bound(splitters.begin() + 1, splitters.end() - 1, key);
  return static_cast<int>(it - splitters.begin()) - 1;
}

KeyBox globalParticleBox(const ParticleSet& p, int dimension, const Communicator& comm) {
  std::vector<double> lo(3, std::numeric_limits<double>::max());
  std::vector<double> hi(3, std::numeric_limits<double>::lowest());
  for (int d = 0; d < dimension; ++d)
    for (std::size_t i = 0; i < p.numReal; ++i) {
      lo[static_cast<std::size_t>(d)] = std::min(lo[static_cast<std::size_t>(d)], p.x[static_cast<std::size_t>(d)][i]);
      hi[static_cast<std::size_t>(d)] = std::max(hi[static_cast<std::size_t>(d)], p.x[static_cast<std::size_t>(d)][i]);
    }
  comm.minInPlace(lo);
  comm.maxInPlace(hi);
  KeyBox box;
  for (std::size_t d = 0; d < 3; ++d) {
    if (static_cast<int>(d) >= dimension || lo[d] > hi[d]) continue;
    const double pad = 1e-9 * std::max(hi[d] - lo[d], std::max(std::abs(hi[d]), 1e-30));
    box.lo[d] = lo[d] - pad;
    box.hi[d] = hi[d] + pad;
  }
  return box;
}

std::vector<std::uint64_t> balancedSplitters(std::span<const std::uint64_t> keys,
                                             std::span<const std::uint64_t> weights,
                                             const Communicator& comm) {
  const std::size_t ranks = static_cast<std::size_t>(comm.size());
  // This rank's keys in order, with the running sum of their weights.
  std::vector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  std::vector<std::uint64_t> sorted(keys.size());
  std::vector<std::uint64_t> cumulative(keys.size() + 1, 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    sorted[k] = keys[order[k]];
    cumulative[k + 1] = cumulative[k] + weights[order[k]];
  }
  // Weight of this rank's keys in [first, last] (closed: `last` may be the largest key).
  auto weightIn = [&](std::uint64_t first, std::uint64_t last) {
    const auto begin = std::lower_bound(sorted.begin(), sorted.end(), first);
    const auto end = std::upper_bound(begin, sorted.end(), last);
    return cumulative[static_cast<std::size_t>(end - sorted.begin())] -
           cumulative[static_cast<std::size_t>(begin - sorted.begin())];
  };
  const std::uint64_t total = comm.sum(cumulative.back());
  // Boundary r (1 .. ranks - 1) goes where the weight below it reaches r / ranks of the total.
  const std::size_t boundaries = ranks - 1;
  std::vector<std::uint64_t> lo(boundaries, 0), below(boundaries, 0), target(boundaries);
  for (std::size_t r = 0; r < boundaries; ++r)  // total (r + 1) / ranks without overflow
    target[r] = total / ranks * (r + 1) + total % ranks * (r + 1) / ranks;
  constexpr int kBins = 256;
  for (int shift = 56; shift >= 0; shift -= 8) {
    // Each splitter's range is [lo, lo + 256 width), aligned, so its last key fits 64 bits.
    const std::uint64_t width = std::uint64_t{1} << shift;
    std::vector<std::uint64_t> histogram(boundaries * kBins);
    for (std::size_t r = 0; r < boundaries; ++r)
      for (std::uint64_t b = 0; b < kBins; ++b)
        histogram[r * kBins + b] = weightIn(lo[r] + width * b, lo[r] + width * b + (width - 1));
    comm.sumInPlace(histogram);
    for (std::size_t r = 0; r < boundaries; ++r) {
      // The bin in which the running weight passes the target (the last bin if it never does).
      std::uint64_t b = 0;
      std::uint64_t running = below[r];
      for (; b < kBins - 1; ++b) {
        const std::uint64_t next = running + histogram[r * kBins + b];
        if (next > target[r]) break;
        running = next;
      }
      lo[r] += width * b;
      below[r] = running;
    }
  }
  std::vector<std::uint64_t> splitters(ranks + 1);
  splitters[0] = 0;
  for (std::size_t r = 0; r < boundaries; ++r) splitters[r + 1] = lo[r];
  splitters[ranks] = std::numeric_limits<std::uint64_t>::max();
  // Keys are monotone in the targets; equal keys may make neighbours equal (an empty rank).
  for (std::size_t r = 1; r <= ranks; ++r) splitters[r] = std::max(splitters[r], splitters[r - 1]);
  return splitters;
}

void migrateParticles(ParticleSet& p, std::span<const int> destination, const Communicator& comm) {
  p.clearGhosts();
  const int me = comm.rank();
  const ParticlePacker packer(p, PackedFields::All);
  std::vector<std::vector<std::size_t>> leaving(static_cast<std::size_t>(comm.size()));
  std::vector<std::size_t> staying;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (destination[i] == me) staying.push_back(i);
    else leaving[static_cast<std::size_t>(destination[i])].push_back(i);
  }
  std::vector<Bytes> out(static_cast<std::size_t>(comm.size()));
  for (std::size_t r = 0; r < out.size(); ++r) packer.pack(p, leaving[r], out[r]);
  const std::vector<Bytes> in = comm.exchange(out);
  std::size_t arriving = 0;
  for (const Bytes& b : in) arriving += packer.count(b);
  if (staying.size() != p.numReal) {
    p.permute(staying);  // keeps the first staying.size() particles, in order
    p.numReal = staying.size();
    p.clearGhosts();
  }
  std::size_t at = p.numReal;
  p.resize(p.numReal + arriving);
  for (const Bytes& b : in) {
    packer.unpack(p, b, at);
    at += packer.count(b);
  }
  p.numReal = p.size();
}

double loadImbalance(double localCost, const Communicator& comm) {
  std::vector<double> cost{localCost};
  std::vector<double> top = cost;
  comm.maxInPlace(top);
  comm.sumInRankOrder(cost);
  const double mean = cost[0] / comm.size();
  return mean > 0.0 ? top[0] / mean - 1.0 : 0.0;
}

}  // namespace ejecta
