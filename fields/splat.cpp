#include "fields/splat.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "sim/sph/kernel.hpp"

namespace ejecta::fields {

namespace {

// A particle or its mirror image across the RZ axis.
struct Emitter {
  std::size_t particle;
  double sign;  // -1: the mirror image (x[0] negated)
};

struct BlockPair {
  std::uint64_t key;
  std::uint32_t emitter;
  bool operator<(const BlockPair& o) const {
    return key != o.key ? key < o.key : emitter < o.emitter;
  }
};

// Voxel index range [lo, hi] whose centres lie within `radius` of `x` along one axis.
inline void voxelRange(double x, double radius, double voxel, int& lo, int& hi) {
  lo = static_cast<int>(std::ceil((x - radius) / voxel));
  hi = static_cast<int>(std::floor((x + radius) / voxel));
}

template <template <int> class Kernel, int D>
SparseLattice splatWith(const SplatSource& src, const std::vector<const double*>& values,
                        double voxel, const std::optional<VoxelBox>& clip) {
  using K = Kernel<D>;
  constexpr int B = SparseLattice::kBlock;
  const int channels = static_cast<int>(values.size()) + 1;

  std::vector<Emitter> emitters;
  emitters.reserve(src.count);
  for (std::size_t j = 0; j < src.count; ++j) {
    if (!(src.h[j] > 0.0) || !std::isfinite(src.h[j]))
      throw std::invalid_argument("splat: particle " + std::to_string(j) +
                                  " has a non-positive smoothing length");
    if (!(src.volume[j] > 0.0) || !std::isfinite(src.volume[j])) continue;  // no material
    emitters.push_back({j, 1.0});
    if (src.mirrorAxis && src.x[0][j] < kKernelSupport * src.h[j]) emitters.push_back({j, -1.0});
  }

  // Every (block, emitter) pair where the emitter's support reaches into the block.
  auto blockRange = [&](const Emitter& e, int (&lo)[3], int (&hi)[3]) {
    const std::size_t j = e.particle;
    const double radius = kKernelSupport * src.h[j];
    for (int d = 0; d < 3; ++d) {
      if (d >= D) { lo[d] = hi[d] = 0; continue; }
      const double xd = d == 0 ? e.sign * src.x[0][j] : src.x[d][j];
      voxelRange(xd, radius, voxel, lo[d], hi[d]);
      if (clip) { lo[d] = std::max(lo[d], clip->lo[d]); hi[d] = std::min(hi[d], clip->hi[d]); }
    }
  };
  std::vector<std::size_t> offsets(emitters.size() + 1, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t e = 0; e < emitters.size(); ++e) {
    int lo[3], hi[3];
    blockRange(emitters[e], lo, hi);
    std::size_t n = 1;
    for (int d = 0; d < 3; ++d)
      n *= hi[d] < lo[d] ? 0 : static_cast<std::size_t>(SparseLattice::blockOf(hi[d]) -
                                                        SparseLattice::blockOf(lo[d]) + 1);
    offsets[e + 1] = n;
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<BlockPair> pairs(offsets.back());
#pragma omp parallel for schedule(static)
  for (std::size_t e = 0; e < emitters.size(); ++e) {
    int lo[3], hi[3];
    blockRange(emitters[e], lo, hi);
    std::size_t out = offsets[e];
    if (offsets[e + 1] == out) continue;
    for (int bi = SparseLattice::blockOf(lo[0]); bi <= SparseLattice::blockOf(hi[0]); ++bi)
      for (int bj = SparseLattice::blockOf(lo[1]); bj <= SparseLattice::blockOf(hi[1]); ++bj)
        for (int bk = SparseLattice::blockOf(lo[2]); bk <= SparseLattice::blockOf(hi[2]); ++bk)
          pairs[out++] = {SparseLattice::blockKey(bi, bj, bk), static_cast<std::uint32_t>(e)};
  }
  std::sort(pairs.begin(), pairs.end());

  // One block per distinct key, in key order.
  SparseLattice lattice(D, voxel, channels);
  std::vector<std::size_t> firstPair;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (p > 0 && pairs[p].key == pairs[p - 1].key) continue;
    firstPair.push_back(p);
    const int bi = static_cast<int>((pairs[p].key >> 42) & 0x1FFFFF) - (1 << 20);
    const int bj = static_cast<int>((pairs[p].key >> 21) & 0x1FFFFF) - (1 << 20);
    const int bk = static_cast<int>(pairs[p].key & 0x1FFFFF) - (1 << 20);
    lattice.addBlock({bi * B, bj * B, D == 3 ? bk * B : 0});
  }
  firstPair.push_back(pairs.size());

  const double sigma = K::sigma;
  std::vector<char> keep(lattice.blockCount(), 0);
#pragma omp parallel
  {
    std::vector<double> weighted(static_cast<std::size_t>(channels));
#pragma omp for schedule(dynamic, 4)
    for (std::size_t b = 0; b < lattice.blockCount(); ++b) {
      const Index3 origin = lattice.blockOrigin(b);
      std::vector<float*> out(static_cast<std::size_t>(channels));
      for (int c = 0; c < channels; ++c) out[c] = lattice.data(b, c);
      for (std::size_t p = firstPair[b]; p < firstPair[b + 1]; ++p) {
        const Emitter& e = emitters[pairs[p].emitter];
        const std::size_t j = e.particle;
        const double h = src.h[j];
        const double radius = kKernelSupport * h;
        const double norm = sigma / std::pow(h, D);
        const double xj[3] = {e.sign * src.x[0][j], src.x[1][j], D == 3 ? src.x[2][j] : 0.0};
        weighted[0] = src.volume[j];
        for (int c = 1; c < channels; ++c) weighted[c] = src.volume[j] * values[c - 1][j];
        int lo[3], hi[3];
        for (int d = 0; d < 3; ++d) {
          if (d >= D) { lo[d] = hi[d] = 0; continue; }
          voxelRange(xj[d], radius, voxel, lo[d], hi[d]);
          lo[d] = std::max(lo[d], origin[d]);
          hi[d] = std::min(hi[d], origin[d] + B - 1);
          if (clip) { lo[d] = std::max(lo[d], clip->lo[d]); hi[d] = std::min(hi[d], clip->hi[d]); }
        }
        for (int i = lo[0]; i <= hi[0]; ++i) {
          const double dx = i * voxel - xj[0];
          for (int jj = lo[1]; jj <= hi[1]; ++jj) {
            const double dy = jj * voxel - xj[1];
            for (int k = lo[2]; k <= hi[2]; ++k) {
              const double dz = D == 3 ? k * voxel - xj[2] : 0.0;
              const double q = std::sqrt(dx * dx + dy * dy + dz * dz) / h;
              if (q >= kKernelSupport) continue;
              double w, dw;
              K::shape(q, w, dw);
              w *= norm;
              const int v = lattice.localIndex(i - origin[0], jj - origin[1], k - origin[2]);
              for (int c = 0; c < channels; ++c) out[c][v] += static_cast<float>(w * weighted[c]);
              keep[b] = 1;
            }
          }
        }
      }
    }
  }
  lattice.compact([&](std::size_t b) { return keep[b] != 0; });
  return lattice;
}

template <int D>
SparseLattice splatDim(const SplatSource& src, const std::vector<const double*>& values,
                       double voxel, const std::optional<VoxelBox>& clip) {
  switch (src.kernel) {
    case KernelKind::CubicSpline: return splatWith<CubicSplineKernel, D>(src, values, voxel, clip);
    case KernelKind::WendlandC2: return splatWith<WendlandC2Kernel, D>(src, values, voxel, clip);
    case KernelKind::WendlandC4: return splatWith<WendlandC4Kernel, D>(src, values, voxel, clip);
  }
  throw std::invalid_argument("splat: unknown kernel");
}

}  // namespace

SparseLattice splat(const SplatSource& source, const std::vector<const double*>& values,
                    double voxel, const std::optional<VoxelBox>& clip) {
  if (!(voxel > 0.0) || !std::isfinite(voxel))
    throw std::invalid_argument("splat: the voxel size must be positive");
  if (source.count >= (std::size_t{1} << 31))
    throw std::invalid_argument("splat: more than 2^31 particles");
  if (source.dims == 3) return splatDim<3>(source, values, voxel, clip);
  if (source.dims == 2) return splatDim<2>(source, values, voxel, clip);
  throw std::invalid_argument("splat: dims must be 2 or 3");
}

}  // namespace ejecta::fields
