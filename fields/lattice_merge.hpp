#pragma once
// A distributed run's grids: each rank splats its own particles, and the lattices are summed at
// rank 0 (an SPH sum over all particles is the sum of the ranks' sums over theirs). Sums are
// merged before any Shepard ratio or level set is formed, since those are not additive; rank 0
// adds the ranks' lattices in rank order, so a run on a fixed number of ranks gives the same
// grid bit for bit. The merged lattice equals the one-rank splat to float round-off.
#include "fields/grid_set.hpp"
#include "fields/sparse_lattice.hpp"
#include "sim/parallel/communicator.hpp"

namespace ejecta::fields {

// Adds `other` into `into` voxel by voxel (blocks `into` lacks are added). Both must have the
// same dimension, voxel and channels; throws std::invalid_argument otherwise.
void accumulate(SparseLattice& into, const SparseLattice& other);

// The lattice as bytes and back (for the gather; the layout is internal).
Bytes latticeBytes(const SparseLattice& lattice);
SparseLattice latticeFromBytes(const Bytes& bytes);

// Every rank's lattice summed, at rank 0 (a collective; elsewhere an empty lattice like mine).
SparseLattice sumOnRoot(const SparseLattice& mine, const Communicator& ranks);

// splatParticles (fields/grid_set.hpp) over every rank's particles (a collective): each rank
// splats its own, rank 0 holds the sum. A rank with no particles adds nothing; an error on any
// rank (a bad smoothing length) is thrown on every rank, as std::invalid_argument. One rank:
// splatParticles itself.
SparseLattice splatEveryRank(const ParticleSet& p, const ParticleContext& ctx,
                             const std::vector<std::vector<double>>& values, double voxel,
                             const std::optional<VoxelBox>& clip, const Communicator& ranks);

// The median smoothing length of every rank's real particles (a collective; the serial
// medianSmoothingLength on one rank). Throws std::invalid_argument on every rank when there
// are none.
double medianSmoothingLength(const ParticleSet& p, const Communicator& ranks);

}  // namespace ejecta::fields
