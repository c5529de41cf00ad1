#include "fields/sparse_lattice.hpp"

#include <cmath>
#include <stdexcept>

namespace ejecta::fields {

SparseLattice::SparseLattice(int dims, double voxel, int channels)
    : dims_(dims), voxel_(voxel), channels_(channels) {
  if (dims != 2 && dims != 3) throw std::invalid_argument("SparseLattice: dims must be 2 or 3");
  if (!(voxel > 0.0)) throw std::invalid_argument("SparseLattice: voxel size must be positive");
  if (channels < 1) throw std::invalid_argument("SparseLattice: at least one channel");
}

std::uint64_t SparseLattice::blockKey(int bi, int bj, int bk) {
  // 21 bits per axis, offset so that negative block indices sort before positive ones.
  constexpr std::int64_t offset = 1 << 20;
  return (static_cast<std::uint64_t>(bi + offset) << 42) |
         (static_cast<std::uint64_t>(bj + offset) << 21) | static_cast<std::uint64_t>(bk + offset);
}

std::size_t SparseLattice::addBlock(const Index3& origin) {
  const std::size_t b = origins_.size();
  origins_.push_back(origin);
  data_.resize(data_.size() + static_cast<std::size_t>(channels_) * blockVolume(), 0.0f);
  index_[blockKey(blockOf(origin[0]), blockOf(origin[1]), blockOf(origin[2]))] = b;
  return b;
}

void SparseLattice::rebuildIndex() {
  index_.clear();
  index_.reserve(origins_.size());
  for (std::size_t b = 0; b < origins_.size(); ++b)
    index_[blockKey(blockOf(origins_[b][0]), blockOf(origins_[b][1]), blockOf(origins_[b][2]))] = b;
}

long SparseLattice::findBlock(int i, int j, int k) const {
  const auto it = index_.find(blockKey(blockOf(i), blockOf(j), dims_ == 3 ? blockOf(k) : 0));
  return it == index_.end() ? -1 : static_cast<long>(it->second);
}

float SparseLattice::value(int channel, int i, int j, int k) const {
  if (dims_ == 2) k = 0;
  const long b = findBlock(i, j, k);
  if (b < 0) return 0.0f;
  constexpr int mask = kBlock - 1;
  return data(static_cast<std::size_t>(b), channel)[localIndex(i & mask, j & mask, k & mask)];
}

double SparseLattice::sample(int channel, const std::array<double, 3>& x) const {
  double t[3];
  int i0[3];
  for (int d = 0; d < 3; ++d) {
    const double s = d < dims_ ? x[d] / voxel_ : 0.0;
    const double f = std::floor(s);
    i0[d] = static_cast<int>(f);
    t[d] = s - f;
  }
  double sum = 0.0;
  const int kCorners = dims_ == 3 ? 2 : 1;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < kCorners; ++c) {
        double w = (a ? t[0] : 1 - t[0]) * (b ? t[1] : 1 - t[1]);
        if (dims_ == 3) w *= c ? t[2] : 1 - t[2];
        if (w == 0.0) continue;
        sum += w * value(channel, i0[0] + a, i0[1] + b, i0[2] + c);
      }
  return sum;
}

}  // namespace ejecta::fields
