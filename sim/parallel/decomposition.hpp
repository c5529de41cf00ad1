#pragma once
// Domain decomposition by a Hilbert curve (sim/parallel/space_filling_curve.hpp): rank r owns
// the particles whose keys lie in [splitter[r], splitter[r + 1]), and the splitters are chosen
// so that each rank's summed cost (a particle's measured work: its neighbour count, more for
// solids) is as close to the total over the number of ranks as whole keys allow.
//
// The splitters are found without gathering the particles: eight rounds of a 256-bin histogram
// of the weights, each round narrowing every splitter's key range by 8 bits (an exact integer
// reduction per round, so every rank finds the same splitters whatever the summation order).
#include <cstdint>
#include <span>
#include <vector>

#include "sim/parallel/communicator.hpp"
#include "sim/parallel/space_filling_curve.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

struct Decomposition {
  KeyBox box;                            // the box the keys were computed in
  std::vector<std::uint64_t> splitters;  // size() + 1 entries: rank r owns [s[r], s[r+1])
  int dimension = 3;
  bool empty() const { return splitters.empty(); }
  // The rank that owns `key`.
  int owner(std::uint64_t key) const;
};

// The box around every rank's real particles (a collective), widened by a hair so that no
// particle sits on its upper face.
KeyBox globalParticleBox(const ParticleSet& p, int dimension, const Communicator& comm);

// Splitters dividing the summed `weights` of every rank's `keys` into comm.size() near-equal
// shares (a collective). keys and weights are this rank's, in any order.
std::vector<std::uint64_t> balancedSplitters(std::span<const std::uint64_t> keys,
                                             std::span<const std::uint64_t> weights,
                                             const Communicator& comm);

// Sends every real particle to `destination[i]` (a collective): this rank keeps those it owns
// and appends those it receives, ordered by sending rank and then by the sender's order. Every
// stored field travels (PackedFields::All); ghosts are dropped first.
void migrateParticles(ParticleSet& p, std::span<const int> destination, const Communicator& comm);

// The largest rank cost over the mean, minus one (0: perfect balance), a collective.
double loadImbalance(double localCost, const Communicator& comm);

}  // namespace ejecta
