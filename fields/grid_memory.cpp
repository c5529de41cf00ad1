#include "fields/grid_memory.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/machine_memory.hpp"
#include "sim/sph/kernel.hpp"

namespace ejecta::fields {

namespace {

// Per voxel: a float per grid and the filled fraction in the lattice, the same again in the
// OpenVDB grids written from it, and the 8^3 blocks' partly filled edges (x2).
double bytesPerVoxel(std::size_t grids) { return 2.0 * 2.0 * 4.0 * static_cast<double>(grids + 1); }

}  // namespace

GridMemoryEstimate estimateGridMemory(const ParticleSet& p, const ParticleContext& ctx,
                                      const GridRequest& request, double voxel, std::size_t grids) {
  GridMemoryEstimate e;
  if (p.numReal == 0 || !(voxel > 0.0)) return e;
  const double support = kKernelSupport;  // 2h for every kernel (sim/sph/kernel.hpp)
  const int layers = request.extrude > 0.0 ? std::max(1, static_cast<int>(std::lround(request.extrude / voxel))) : 1;
  std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  double footprints = 0.0;
  double reach = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double r = support * p.h[i];
    const double across = 2.0 * r / voxel + 1.0;
    reach = std::max(reach, r);
    switch (ctx.geometry) {
      case Geometry::Spatial: footprints += across * across * across; break;
      case Geometry::Planar: footprints += across * across * layers; break;
      case Geometry::Axisymmetric:
        footprints += across * across * (2.0 * std::numbers::pi * (std::abs(p.x[0][i]) + r) / voxel + 1.0);
        break;
      case Geometry::Line: break;
    }
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], p.x[d][i]), hi[d] = std::max(hi[d], p.x[d][i]);
  }
  // The bounding box in 3D grid coordinates: RZ's (r, z) revolved about the z axis (grid y).
  std::array<double, 3> boxLo{}, boxHi{};
  for (int d = 0; d < 3; ++d) boxLo[d] = lo[d] - reach, boxHi[d] = hi[d] + reach;
  if (ctx.geometry == Geometry::Axisymmetric) {
    const double rmax = std::max(std::abs(lo[0]), std::abs(hi[0])) + reach;
    boxLo = {-rmax, lo[1] - reach, -rmax};
    boxHi = {rmax, hi[1] + reach, rmax};
  }
  if (request.clip)
    for (int d = 0; d < 3; ++d)
      boxLo[d] = std::max(boxLo[d], request.regionMin[d]), boxHi[d] = std::min(boxHi[d], request.regionMax[d]);
  double box = 1.0;
  for (int d = 0; d < 3; ++d) {
    const bool slab = ctx.geometry == Geometry::Planar && d == 2;
    box *= slab ? layers : std::max(boxHi[d] - boxLo[d], 0.0) / voxel + 1.0;
  }
  e.voxels = std::min(footprints, box);
  e.bytes = e.voxels * bytesPerVoxel(grids);
  return e;
}

void requireGridMemory(const ParticleSet& p, const ParticleContext& ctx, const GridRequest& request,
                       double voxel, std::size_t grids) {
  const GridMemoryEstimate e = estimateGridMemory(p, ctx, request, voxel, grids);
  char what[96], detail[96];
  std::snprintf(what, sizeof what, "the grid set at voxel %.3g m", voxel);
  std::snprintf(detail, sizeof detail, "about %.3g voxels x %zu grids", e.voxels, grids);
  requireMemory(what, e.bytes, detail,
                "give a coarser voxel ([fields] voxel or --voxel; the default is the median "
                "smoothing length) or a [fields] region");
}

}  // namespace ejecta::fields
