#pragma once
// Neighbour lists of one step.
//   gather(i): the particles j within the support of particle i's own kernel, |x_ij| < 2 h_i,
//              found by the density pass (for real particles) or by findGhostGathers (ghosts).
//   pairs(i):  every j that interacts with real particle i in the force pass,
//              |x_ij| < 2 max(h_i, h_j): gather(i) plus the j whose larger kernel reaches i.
// Lists are filled per thread and addressed per particle, so their content does not depend on
// the thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "sim/sph/cell_grid.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

class NeighbourLists {
 public:
  // Prepares storage for `numParticles` gather lists and `numThreads` buffers.
  void reset(std::size_t numParticles, int numThreads);
  // Thread `t` appends particle i's gather list.
  void storeGather(int t, std::size_t i, const std::uint32_t* js, std::size_t count);
  std::span<const std::uint32_t> gather(std::size_t i) const {
    return {buffers_[owner_[i]].data() + start_[i], count_[i]};
  }
  // Gather lists for ghosts (2 h_ghost), needed to find ghosts whose support reaches a real.
  template <int D>
  void findGhostGathers(const ParticleSet& p, const CellGrid& grid, double support);
  // Builds pairs() for the real particles from the gather lists.
  template <int D>
  void buildPairs(const ParticleSet& p, double support);
  // Individual time steps: pairs() for the `active` real particles only (the others get none),
  // from their gather lists and the grid's reach (CellGrid::recordReach), in the order
  // buildPairs gives them.
  template <int D>
  void buildActivePairs(const ParticleSet& p, const CellGrid& grid, double support,
                        const std::vector<std::size_t>& active);
  // How many real particles pairs() was last built for (0: none yet).
  std::size_t pairedParticles() const { return pairStart_.empty() ? 0 : pairStart_.size() - 1; }
  std::span<const std::uint32_t> pairs(std::size_t i) const {
    return {pairs_.data() + pairStart_[i], pairStart_[i + 1] - pairStart_[i]};
  }

 private:
  std::vector<std::vector<std::uint32_t>> buffers_;
  std::vector<std::uint32_t> owner_;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> count_;
  std::vector<std::size_t> pairStart_;
  std::vector<std::uint32_t> pairs_;
};

}  // namespace ejecta
