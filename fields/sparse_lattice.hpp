#pragma once
// SparseLattice: voxels in 2 or 3 dimensions, allocated in blocks of 8^D where material is, each
// voxel holding a few float channels. Blocks are the size and voxel order of an OpenVDB leaf
// node, so a 3D block becomes a leaf by a copy (fields/vdb_grids.cpp); keeping OpenVDB out of
// this header keeps it out of the hot splatting code and out of most translation units.
// Voxel (i, j, k) has its centre at (i, j, k) * voxel: OpenVDB's cell-centred convention.
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace ejecta::fields {

using Index3 = std::array<int, 3>;

class SparseLattice {
 public:
  static constexpr int kLog2Block = 3;
  static constexpr int kBlock = 1 << kLog2Block;  // voxels per block side

  SparseLattice() = default;
  // dims: 2 (k = 0 only) or 3.
  SparseLattice(int dims, double voxel, int channels);

  int dims() const { return dims_; }
  double voxel() const { return voxel_; }
  int channels() const { return channels_; }
  int blockVolume() const { return dims_ == 3 ? kBlock * kBlock * kBlock : kBlock * kBlock; }
  std::size_t blockCount() const { return origins_.size(); }
  std::size_t voxelCapacity() const { return blockCount() * static_cast<std::size_t>(blockVolume()); }

  // Voxel index of the block's first voxel (multiples of 8; k = 0 in 2D).
  const Index3& blockOrigin(std::size_t b) const { return origins_[b]; }
  // The block's values of one channel, blockVolume() of them in localIndex order.
  float* data(std::size_t b, int channel) {
    return data_.data() + (b * channels_ + channel) * static_cast<std::size_t>(blockVolume());
  }
  const float* data(std::size_t b, int channel) const {
    return data_.data() + (b * channels_ + channel) * static_cast<std::size_t>(blockVolume());
  }
  // Position of voxel (lx, ly, lz) in its block: x slowest, as in an OpenVDB leaf.
  int localIndex(int lx, int ly, int lz) const {
    return dims_ == 3 ? (lx * kBlock + ly) * kBlock + lz : lx * kBlock + ly;
  }

  // Appends a zeroed block whose origin is `origin` (a multiple of 8, not yet present).
  std::size_t addBlock(const Index3& origin);
  // Drops blocks for which keep(b) is false, keeping the order of the rest.
  template <typename Keep>
  void compact(Keep keep);

  // The block holding voxel (i, j, k), or -1.
  long findBlock(int i, int j, int k) const;
  // One voxel's value; 0 where no block is allocated.
  float value(int channel, int i, int j, int k) const;
  // Multilinear interpolation between voxel centres at the point x [m] (2D: x[2] ignored);
  // unallocated voxels count as 0.
  double sample(int channel, const std::array<double, 3>& x) const;

  static std::uint64_t blockKey(int bi, int bj, int bk);
  static int blockOf(int voxelIndex) { return voxelIndex >> kLog2Block; }  // floor division

 private:
  void rebuildIndex();

  int dims_ = 3;
  double voxel_ = 1.0;
  int channels_ = 0;
  std::vector<Index3> origins_;
  std::vector<float> data_;  // [block][channel][voxel]
  std::unordered_map<std::uint64_t, std::size_t> index_;
};

template <typename Keep>
void SparseLattice::compact(Keep keep) {
  const std::size_t stride = static_cast<std::size_t>(channels_) * blockVolume();
  std::size_t out = 0;
  for (std::size_t b = 0; b < origins_.size(); ++b) {
    if (!keep(b)) continue;
    if (out != b) {
      origins_[out] = origins_[b];
      std::copy(data_.begin() + b * stride, data_.begin() + (b + 1) * stride,
                data_.begin() + out * stride);
    }
    ++out;
  }
  origins_.resize(out);
  data_.resize(out * stride);
  rebuildIndex();
}

}  // namespace ejecta::fields
