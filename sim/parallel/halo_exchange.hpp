#pragma once
// Halos: copies of other ranks' particles within kernel reach of this rank's own, appended after
// this rank's ghosts (ParticleSet::ghostSource = kRemoteSource), so the density and force passes
// see every neighbour exactly as a one-rank run does.
//
// Which particles: rank A sends particle j (a real one, or one of A's wall, axis and periodic
// images) to rank B when j lies within max(R_B, k h_j) of the box around B's real particles,
// R_B being the largest k h of B's real particles and k the kernel support with its margin. Any
// pair i (on B), j with |x_ij| < k max(h_i, h_j) then has j on B, since the distance from j to
// B's box is at most |x_ij|. The boxes are exact for any decomposition, so correctness never
// depends on how compact the ranks' domains are, only the halo's size does.
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "sim/parallel/communicator.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// ghostSource of a halo particle: its source lives on another rank.
inline constexpr std::size_t kRemoteSource = std::numeric_limits<std::size_t>::max();

class HaloExchange {
 public:
  // Appends the halos of this rank (a collective). Call after the boundary ghosts are made:
  // those of other ranks are among what arrives. `supportFactor` is the kernel support times
  // the margin h may grow by before the halos must be rebuilt.
  void build(ParticleSet& p, int dimension, double supportFactor, const Communicator& comm);
  // Recopies the halo fields' values (positions apart) from their owners (a collective), after
  // a pass changed them and the boundary ghosts were refreshed.
  void refresh(ParticleSet& p, const Communicator& comm) const;
  // The same for a per-particle array of the workspace holding `stride` values per particle
  // (a velocity gradient, 9), sized for every particle, halos included.
  void refreshArray(std::vector<double>& values, int stride, const Communicator& comm) const;

  std::size_t received() const { return received_; }
  std::size_t sent() const;

 private:
  std::vector<std::vector<std::size_t>> sendTo_;  // per rank: local indices sent there
  std::vector<std::size_t> firstFrom_;            // per rank: index of its first halo here
  std::size_t received_ = 0;
};

}  // namespace ejecta
