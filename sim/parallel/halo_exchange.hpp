#pragma once
// Halos: copies of other ranks' particles within kernel reach of this rank's own, appended after
// this rank's ghosts (ParticleSet::ghostSource = kRemoteSource), so the density and force passes
// see every neighbour exactly as a one-rank run does.
//
// Which particles: each rank describes its real particles by a few dozen boxes (the tight box of
// each occupied cell of a 4 x 4 x 4 grid over them; 64 segments in 1D, 8 x 8 in 2D) and R, the
// largest k h among them, k being the kernel support with the margin h may grow by before the
// halos must be rebuilt. Rank A sends particle j (a real one, or one of A's wall, axis and
// periodic images) to rank B when j lies within max(R_B, k h_j) of one of B's boxes. Any pair
// i (on B), j with |x_ij| < k max(h_i, h_j) then has j on B, since i lies in one of B's boxes
// and the distance from j to that box is at most |x_ij|. The boxes cover the particles whatever
// the decomposition, so correctness never depends on how compact the ranks' domains are, only
// the halo's size does; the grid of boxes keeps it close to the exact halo where a rank's piece
// of the Hilbert curve is ragged (docs/parallel.md).
//
// Cost: messages go only between neighbouring ranks (whose extents come within reach of each
// other), and a rank tests only its particles in cells near a neighbour's boxes.
#include <cstddef>
#include <limits>
#include <memory>
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
  // refresh() in two halves, so that work reading no halo value runs while the messages travel
  // (the force pass's interior, sim/sph/hydro_force.hpp): startRefresh packs this rank's values
  // and sends them; finishRefresh waits and writes what arrived into the halos. The sizes are
  // known from the build, so each partner gets one message.
  std::unique_ptr<Communicator::PendingExchange> startRefresh(const ParticleSet& p,
                                                              const Communicator& comm) const;
  void finishRefresh(ParticleSet& p, Communicator::PendingExchange& pending) const;
  // The same for a per-particle array of the workspace holding `stride` values per particle
  // (a velocity gradient, 9), sized for every particle, halos included.
  void refreshArray(std::vector<double>& values, int stride, const Communicator& comm) const;

  std::size_t received() const { return received_; }
  std::size_t sent() const;
  // The ranks this one sends to and receives from (its neighbours at the last build).
  std::size_t partners() const { return sendRanks_.size(); }

 private:
  std::vector<int> sendRanks_;                    // neighbours that may receive from this rank
  std::vector<std::vector<std::size_t>> sendTo_;  // per send rank: local indices sent there
  std::vector<int> recvRanks_;                    // neighbours that may send to this rank
  std::vector<std::size_t> firstFrom_;            // per receive rank: index of its first halo
  std::vector<std::size_t> countFrom_;            // per receive rank: its halos here
  std::size_t received_ = 0;
};

}  // namespace ejecta
