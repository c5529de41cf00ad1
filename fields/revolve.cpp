#include "fields/revolve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace ejecta::fields {

namespace {

constexpr int B = SparseLattice::kBlock;

// The four voxels around a 2D point and their bilinear weights.
struct Stencil2 {
  long block[4];
  int local[4];
  double weight[4];
};

Stencil2 stencilAt(const SparseLattice& lat, double r, double z) {
  Stencil2 s{};
  const double si = r / lat.voxel(), sj = z / lat.voxel();
  const int i0 = static_cast<int>(std::floor(si)), j0 = static_cast<int>(std::floor(sj));
  const double ti = si - i0, tj = sj - j0;
  for (int c = 0; c < 4; ++c) {
    const int i = i0 + (c >> 1), j = j0 + (c & 1);
    s.weight[c] = ((c >> 1) ? ti : 1 - ti) * ((c & 1) ? tj : 1 - tj);
    s.block[c] = s.weight[c] > 0.0 ? lat.findBlock(i, j, 0) : -1;
    s.local[c] = lat.localIndex(i & (B - 1), j & (B - 1), 0);
  }
  return s;
}

double interpolate(const SparseLattice& lat, const Stencil2& s, int channel) {
  double v = 0.0;
  for (int c = 0; c < 4; ++c)
    if (s.block[c] >= 0) v += s.weight[c] * lat.data(static_cast<std::size_t>(s.block[c]), channel)[s.local[c]];
  return v;
}

// Distance range (in voxels) from the axis to the integer points of the square block (bx, bz).
void blockRadii(int bx, int bz, double& rmin, double& rmax) {
  auto nearest = [](int lo, int hi) { return lo > 0 ? lo : (hi < 0 ? hi : 0); };
  auto farthest = [](int lo, int hi) { return std::abs(lo) > std::abs(hi) ? lo : hi; };
  const int x0 = bx * B, x1 = x0 + B - 1, z0 = bz * B, z1 = z0 + B - 1;
  rmin = std::hypot(nearest(x0, x1), nearest(z0, z1));
  rmax = std::hypot(farthest(x0, x1), farthest(z0, z1));
}

template <typename Fill>
SparseLattice fillBlocks(const SparseLattice& src, std::vector<std::uint64_t> keys, Fill fill) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  SparseLattice out(3, src.voxel(), src.channels());
  for (std::uint64_t key : keys) {
    const int bi = static_cast<int>((key >> 42) & 0x1FFFFF) - (1 << 20);
    const int bj = static_cast<int>((key >> 21) & 0x1FFFFF) - (1 << 20);
    const int bk = static_cast<int>(key & 0x1FFFFF) - (1 << 20);
    out.addBlock({bi * B, bj * B, bk * B});
  }
  std::vector<char> keep(out.blockCount(), 0);
#pragma omp parallel for schedule(dynamic, 8)
  for (std::size_t b = 0; b < out.blockCount(); ++b) keep[b] = fill(out, b) ? 1 : 0;
  out.compact([&](std::size_t b) { return keep[b] != 0; });
  return out;
}

}  // namespace

SparseLattice revolveAboutAxis(const SparseLattice& rz, const std::optional<VoxelBox>& clip) {
  if (rz.dims() != 2) throw std::invalid_argument("revolveAboutAxis: needs a 2D (r, z) lattice");
  std::vector<std::uint64_t> keys;
  for (std::size_t b = 0; b < rz.blockCount(); ++b) {
    const Index3& o = rz.blockOrigin(b);
    // Bilinear interpolation reaches one voxel beyond the block.
    const double rlo = std::max(0.0, o[0] - 1.0), rhi = o[0] + B;
    if (rhi < 0.0) continue;
    const int reach = static_cast<int>(std::ceil(rhi / B));
    for (int bx = -reach - 1; bx <= reach; ++bx)
      for (int bz = -reach - 1; bz <= reach; ++bz) {
        double rmin, rmax;
        blockRadii(bx, bz, rmin, rmax);
        if (rmax < rlo || rmin > rhi) continue;
        for (int by : {SparseLattice::blockOf(o[1] - 1), SparseLattice::blockOf(o[1]),
                       SparseLattice::blockOf(o[1] + B)})
          keys.push_back(SparseLattice::blockKey(bx, by, bz));
      }
  }
  const int channels = rz.channels();
  return fillBlocks(rz, std::move(keys), [&](SparseLattice& out, std::size_t b) {
    const Index3 o = out.blockOrigin(b);
    const double h = out.voxel();
    bool any = false;
    for (int lx = 0; lx < B; ++lx)
      for (int ly = 0; ly < B; ++ly)
        for (int lz = 0; lz < B; ++lz) {
          const int i = o[0] + lx, j = o[1] + ly, k = o[2] + lz;
          if (clip && !clip->contains(i, j, k)) continue;
          const Stencil2 s = stencilAt(rz, std::hypot(i * h, k * h), j * h);
          const double filled = interpolate(rz, s, 0);
          if (!(filled > 0.0)) continue;
          const int v = out.localIndex(lx, ly, lz);
          out.data(b, 0)[v] = static_cast<float>(filled);
          for (int c = 1; c < channels; ++c)
            out.data(b, c)[v] = static_cast<float>(interpolate(rz, s, c));
          any = true;
        }
    return any;
  });
}

SparseLattice extrudeSlab(const SparseLattice& planar, int layers,
                          const std::optional<VoxelBox>& clip) {
  if (planar.dims() != 2) throw std::invalid_argument("extrudeSlab: needs a 2D lattice");
  if (layers < 1) throw std::invalid_argument("extrudeSlab: at least one layer");
  std::vector<std::uint64_t> keys;
  for (std::size_t b = 0; b < planar.blockCount(); ++b) {
    const Index3& o = planar.blockOrigin(b);
    for (int bk = 0; bk <= (layers - 1) / B; ++bk)
      keys.push_back(SparseLattice::blockKey(o[0] / B, o[1] / B, bk));
  }
  const int channels = planar.channels();
  return fillBlocks(planar, std::move(keys), [&](SparseLattice& out, std::size_t b) {
    const Index3 o = out.blockOrigin(b);
    const long src = planar.findBlock(o[0], o[1], 0);
    if (src < 0) return false;
    bool any = false;
    for (int lx = 0; lx < B; ++lx)
      for (int ly = 0; ly < B; ++ly) {
        const int from = planar.localIndex(lx, ly, 0);
        if (!(planar.data(static_cast<std::size_t>(src), 0)[from] > 0.0f)) continue;
        for (int lz = 0; lz < B && o[2] + lz < layers; ++lz) {
          if (clip && !clip->contains(o[0] + lx, o[1] + ly, o[2] + lz)) continue;
          const int v = out.localIndex(lx, ly, lz);
          for (int c = 0; c < channels; ++c)
            out.data(b, c)[v] = planar.data(static_cast<std::size_t>(src), c)[from];
          any = true;
        }
      }
    return any;
  });
}

}  // namespace ejecta::fields
