#include "fields/lattice_merge.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "sim/parallel/order_statistics.hpp"

namespace ejecta::fields {

void accumulate(SparseLattice& into, const SparseLattice& other) {
  if (into.dims() != other.dims() || into.voxel() != other.voxel() || into.channels() != other.channels())
    throw std::invalid_argument("accumulate: lattices of different dimension, voxel or channels");
  const int volume = other.blockVolume();
  for (std::size_t b = 0; b < other.blockCount(); ++b) {
    const Index3& origin = other.blockOrigin(b);
    long t = into.findBlock(origin[0], origin[1], origin[2]);
    if (t < 0) t = static_cast<long>(into.addBlock(origin));
    for (int c = 0; c < other.channels(); ++c) {
      float* out = into.data(static_cast<std::size_t>(t), c);
      const float* in = other.data(b, c);
      for (int v = 0; v < volume; ++v) out[v] += in[v];
    }
  }
}

namespace {

struct LatticeHeader {
  std::int64_t dims = 3, channels = 1, blocks = 0;
  double voxel = 1.0;
};

}  // namespace

Bytes latticeBytes(const SparseLattice& lattice) {
  const LatticeHeader header{lattice.dims(), lattice.channels(),
                             static_cast<std::int64_t>(lattice.blockCount()), lattice.voxel()};
  const std::size_t values = static_cast<std::size_t>(lattice.channels() * lattice.blockVolume());
  // Sized once and filled by memcpy: the layout latticeFromBytes reads.
  Bytes out(sizeof header + lattice.blockCount() * (sizeof(Index3) + values * sizeof(float)));
  std::byte* at = out.data();
  std::memcpy(at, &header, sizeof header);
  at += sizeof header;
  for (std::size_t b = 0; b < lattice.blockCount(); ++b, at += sizeof(Index3))
    std::memcpy(at, lattice.blockOrigin(b).data(), sizeof(Index3));
  for (std::size_t b = 0; b < lattice.blockCount(); ++b, at += values * sizeof(float))
    std::memcpy(at, lattice.data(b, 0), values * sizeof(float));
  return out;
}

SparseLattice latticeFromBytes(const Bytes& bytes) {
  LatticeHeader header;
  if (bytes.size() < sizeof header) throw std::invalid_argument("latticeFromBytes: truncated header");
  std::copy(bytes.begin(), bytes.begin() + sizeof header, reinterpret_cast<std::byte*>(&header));
  SparseLattice lattice(static_cast<int>(header.dims), header.voxel, static_cast<int>(header.channels));
  const std::size_t blocks = static_cast<std::size_t>(header.blocks);
  const std::size_t values = static_cast<std::size_t>(lattice.channels() * lattice.blockVolume());
  if (bytes.size() != sizeof header + blocks * (sizeof(Index3) + values * sizeof(float)))
    throw std::invalid_argument("latticeFromBytes: size does not match its header");
  const std::byte* at = bytes.data() + sizeof header;
  for (std::size_t b = 0; b < blocks; ++b, at += sizeof(Index3)) {
    Index3 origin;
    std::copy(at, at + sizeof origin, reinterpret_cast<std::byte*>(origin.data()));
    lattice.addBlock(origin);
  }
  for (std::size_t b = 0; b < blocks; ++b, at += values * sizeof(float))
    std::copy(at, at + values * sizeof(float), reinterpret_cast<std::byte*>(lattice.data(b, 0)));
  return lattice;
}

SparseLattice sumOnRoot(const SparseLattice& mine, const Communicator& ranks) {
  if (ranks.size() == 1) return mine;
  const std::vector<Bytes> all = ranks.gatherToRoot(latticeBytes(mine));
  SparseLattice sum(mine.dims(), mine.voxel(), mine.channels());
  for (const Bytes& b : all) accumulate(sum, latticeFromBytes(b));  // rank order (root: all)
  return sum;
}

SparseLattice splatEveryRank(const ParticleSet& p, const ParticleContext& ctx,
                             const std::vector<std::vector<double>>& values, double voxel,
                             const std::optional<VoxelBox>& clip, const Communicator& ranks) {
  if (ranks.size() == 1) return splatParticles(p, ctx, values, voxel, clip);
  const int dims = spatialDimension(ctx.geometry);
  SparseLattice mine(dims == 3 ? 3 : 2, voxel, static_cast<int>(values.size()) + 1);
  std::string error;
  try {
    if (ctx.geometry == Geometry::Line) throw std::invalid_argument("fields: 1D runs have no grids");
    if (p.numReal > 0) mine = splatParticles(p, ctx, values, voxel, clip);
  } catch (const std::exception& e) {
    error = e.what();
  }
  // Every rank stops alike, or none does (the others would wait in the gather).
  error = ranks.firstMessage(error);
  if (!error.empty()) throw std::invalid_argument(error);
  return sumOnRoot(mine, ranks);
}

double medianSmoothingLength(const ParticleSet& p, const Communicator& ranks) {
  if (ranks.size() == 1) return medianSmoothingLength(p);
  if (ranks.sum(p.numReal) == 0) throw std::invalid_argument("fields: the particle set is empty");
  return upperMedian({p.h.data(), p.numReal}, ranks);
}

}  // namespace ejecta::fields
