#pragma once
// The Riemann problems of the pairs a Godunov force pass sums from both sides, solved once.
//
// The force pass gathers: particle i sums its pairs into its own derivatives, and j, when the
// pass sums it too, sums the same pair again. The pair's star state is the same from either side
// to the last bit (pairStar solves it with the lower index on the left), and its solver was a
// third of the 3D Sedov's time (perf; 85% of the solves on time bins and 92% with global steps
// were of pairs whose two particles the pass sums). So before the pass, each such pair is solved
// by its lower particle, and the upper one reads the stored state mirrored. The pairs with a
// ghost, a halo or a particle the pass does not sum keep their own solve in the pass.
//
// Deterministic: every state is computed by one thread from the pair alone, and each particle's
// incoming states are read through a map keyed by the partner, so the order in which the threads
// file them does not matter.
#include <omp.h>

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/sph/neighbour_lists.hpp"
#include "sim/sph/terms/riemann_dissipation.hpp"

namespace ejecta {

class SharedPairStars {
 public:
  static constexpr std::uint32_t kNotShared = 0xffffffffu;
  static constexpr std::uint32_t kIncoming = 0x80000000u;  // index() of a state a lower one solved

  // Solves solve(i, j) for every particle i the pass sums (`summed`, or every real particle with
  // nullptr) and every partner j in its pairs that the pass sums too with j > i. The pair lists
  // must be symmetric between summed particles (each lists the other or neither; they are, by
  // |x_ij| < 2 max(h_i, h_j) in the same bits from either side): checked, a logic_error if not.
  // Memory: 36 bytes a shared pair, and a map of 4 bytes a real particle per thread.
  template <class Solve>
  void solveAll(const NeighbourLists& lists, std::size_t numReal,
                const std::vector<std::size_t>* summed, Solve&& solve);

  // Particle i's walk over its pairs (call index() for every partner, in the pairs' order), with
  // the map of thread `thread`.
  class Walk {
   public:
    // Where the pair (i, j) is stored, kNotShared if the pass solves it itself.
    std::uint32_t index(std::uint32_t j) {
      if (!stars_.summed(j) || j == i_) return kNotShared;
      return j > i_ ? next_++ : map_[j];
    }

   private:
    friend class SharedPairStars;
    Walk(const SharedPairStars& s, std::size_t i, std::uint32_t next, const std::uint32_t* map)
        : stars_(s), i_(i), next_(next), map_(map) {}
    const SharedPairStars& stars_;
    std::size_t i_;
    std::uint32_t next_;
    const std::uint32_t* map_;
  };
  Walk walk(std::size_t i, int thread);

  // The stored state of a pair as the particle that walked to it sees it: its own if it is the
  // lower, otherwise mirrored (the same pressure, the contact's velocity along the opposite axis).
  StarState star(std::uint32_t index) const {
    if (!(index & kIncoming)) return stars_[index];
    const StarState& s = incomingStars_[index & ~kIncoming];
    return {s.P, -s.u};
  }

 private:
  bool summed(std::size_t j) const {
    return j < numReal_ && (allSummed_ || position_[j] != 0);
  }
  std::size_t positionOf(std::size_t i) const { return allSummed_ ? i : position_[i] - 1; }

  std::size_t numReal_ = 0;
  bool allSummed_ = true;
  std::vector<std::uint32_t> position_;  // a summed particle's place in the list plus one; 0: not
  std::vector<std::uint32_t> ownStart_;  // per place: where its own solves begin in stars_
  std::vector<StarState> stars_;
  std::vector<std::uint32_t> incomingStart_;  // per place: its states solved by lower partners
  std::vector<StarState> incomingStars_;
  std::vector<std::uint32_t> incomingFrom_;   // the lower partner of each incoming state
  std::vector<std::uint32_t> fill_;
  std::vector<std::vector<std::uint32_t>> maps_;  // per thread: partner -> stored state
};

template <class Solve>
void SharedPairStars::solveAll(const NeighbourLists& lists, std::size_t numReal,
                               const std::vector<std::size_t>* summed, Solve&& solve) {
  numReal_ = numReal;
  allSummed_ = summed == nullptr;
  const std::size_t count = summed ? summed->size() : numReal;
  auto particle = [&](std::size_t at) { return summed ? (*summed)[at] : at; };
  if (summed) {
    position_.assign(numReal, 0);
    for (std::size_t at = 0; at < count; ++at)
      position_[(*summed)[at]] = static_cast<std::uint32_t>(at + 1);
  }
  // How many pairs each particle solves (its summed partners above it), and how many its
  // partners below it solve for it. The upper particle finds a state through its own pair list,
  // so the lists must be symmetric between summed particles (|x_ij| < 2 max(h_i, h_j) from
  // either side, with the same bits): checked here by counting, since a partner whose state is
  // missing would read another particle's.
  std::vector<std::size_t> own(count + 1, 0), incoming(count + 1, 0), below(count, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t at = 0; at < count; ++at) {
    const std::size_t i = particle(at);
    std::size_t n = 0;
    for (std::uint32_t j : lists.pairs(i)) {
      if (!this->summed(j) || j == i) continue;
      if (j < i) {
        ++below[at];
        continue;
      }
      ++n;
      std::atomic_ref<std::size_t>(incoming[positionOf(j) + 1]).fetch_add(1, std::memory_order_relaxed);
    }
    own[at + 1] = n;
  }
  for (std::size_t at = 0; at < count; ++at)
    if (below[at] != incoming[at + 1])
      throw std::logic_error("riemann dissipation: particle " + std::to_string(particle(at)) +
                             " pairs with " + std::to_string(below[at]) +
                             " summed particles below it, which list it " +
                             std::to_string(incoming[at + 1]) + " times");
  for (std::size_t at = 0; at < count; ++at) {
    own[at + 1] += own[at];
    incoming[at + 1] += incoming[at];
  }
  const std::size_t total = own[count];
  if (total >= kIncoming)  // more pairs than one rank's indices address
    throw std::length_error("riemann dissipation: " + std::to_string(total) +
                            " shared pairs, more than its 31-bit indices address; coarsen the "
                            "spacing or use the viscosity (sph.dissipation = \"viscosity\")");
  ownStart_.assign(own.begin(), own.end());
  incomingStart_.assign(incoming.begin(), incoming.end());
  stars_.resize(total);
  incomingStars_.resize(total);
  incomingFrom_.resize(total);
  // Each state twice: in the lower particle's own run, read in its pairs' order, and in the upper
  // one's incoming states, so that each side reads its own contiguous run.
  std::vector<std::uint32_t>& fill = fill_;
  fill.assign(incomingStart_.begin(), incomingStart_.end() - 1);
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t at = 0; at < count; ++at) {
    const std::size_t i = particle(at);
    std::uint32_t m = ownStart_[at];
    for (std::uint32_t j : lists.pairs(i)) {
      if (!(j > i && this->summed(j))) continue;
      const StarState star = solve(i, j);
      stars_[m++] = star;
      const std::uint32_t slot = std::atomic_ref<std::uint32_t>(fill[positionOf(j)])
                                     .fetch_add(1, std::memory_order_relaxed);
      incomingStars_[slot] = star;
      incomingFrom_[slot] = static_cast<std::uint32_t>(i);
    }
  }
  maps_.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (auto& map : maps_)
    if (map.size() < numReal) map.resize(numReal);
}

inline SharedPairStars::Walk SharedPairStars::walk(std::size_t i, int thread) {
  const std::size_t at = positionOf(i);
  std::uint32_t* map = maps_[static_cast<std::size_t>(thread)].data();
  for (std::uint32_t s = incomingStart_[at]; s < incomingStart_[at + 1]; ++s)
    map[incomingFrom_[s]] = s | kIncoming;
  return Walk(*this, i, ownStart_[at], map);
}

}  // namespace ejecta
