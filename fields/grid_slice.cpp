// Slices and point samples of a grid file. The one translation unit of the sampler that
// includes OpenVDB.
#include "fields/grid_slice.hpp"
#include "fields/vdb_file.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Count.h>
#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace ejecta::fields {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxSamples = 16384;

std::string metaString(const openvdb::MetaMap& m, const std::string& key) {
  const auto p = m.getMetadata<openvdb::StringMetadata>(key);
  return p ? p->value() : std::string();
}

void openFile(openvdb::io::File& file, const std::string& path) { openGridFile(file, path); }

// The header from a grid's metadata and transform (the tree need not be loaded); `box` is the
// active voxels' index box when known.
GridHeader headerOf(const openvdb::GridBase& g, const openvdb::MetaMap& fileMeta,
                    const std::optional<openvdb::CoordBBox>& box) {
  GridHeader h;
  h.name = g.getName();
  h.gridClass = openvdb::GridBase::gridClassToString(g.getGridClass());
  h.units = metaString(g, "units");
  h.scene = metaString(g, "scene");
  h.sourceGeometry = metaString(g, "source_geometry");
  if (const auto t = g.getMetadata<openvdb::DoubleMetadata>("time")) h.time = t->value();
  if (const auto s = g.getMetadata<openvdb::Int64Metadata>("step")) h.step = static_cast<long>(s->value());
  h.voxelSize = g.voxelSize()[0];
  if (const auto d = fileMeta.getMetadata<openvdb::DoubleMetadata>("crater_target_density"))
    h.targetDensity = d->value();
  h.lo = {1.0, 1.0, 1.0};
  h.hi = {-1.0, -1.0, -1.0};
  std::optional<openvdb::CoordBBox> b = box;
  if (!b) {
    // OpenVDB stores the active box with every grid it writes (file_bbox_min/max).
    const auto lo = g.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
    const auto hi = g.getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
    if (lo && hi) b = openvdb::CoordBBox(openvdb::Coord(lo->value()), openvdb::Coord(hi->value()));
  }
  if (b && !b->empty()) {
    const double a = h.voxelSize;
    for (int d = 0; d < 3; ++d) {
      h.lo[d] = (b->min()[d] - 0.5) * a;
      h.hi[d] = (b->max()[d] + 0.5) * a;
    }
  }
  return h;
}

struct LoadedGrid {
  openvdb::FloatGrid::Ptr grid;
  GridHeader header;
};

LoadedGrid loadGrid(const std::string& path, const std::string& name) {
  openvdb::io::File file(path);
  openFile(file, path);
  requireGrid(file, path, name);
  const openvdb::MetaMap::Ptr fileMeta = file.getMetadata();
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
  file.close();
  if (!grid) throw std::runtime_error(path + ": grid '" + name + "' is not a float grid");
  if (!grid->transform().isLinear() || !grid->hasUniformVoxels())
    throw std::runtime_error(path + ": grid '" + name + "' does not have cubic voxels on a linear transform");
  const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
  GridHeader header = headerOf(*grid, *fileMeta, box);
  return {grid, header};
}

// The sampling rule of grid_slice.hpp (NearestInactive or AllInactive), with one accessor per
// thread.
class ActiveSampler {
 public:
  ActiveSampler(const openvdb::FloatGrid& grid, bool nearestMustBeActive)
      : grid_(grid), accessor_(grid.getConstAccessor()), nearest_(nearestMustBeActive) {}

  double operator()(const std::array<double, 3>& world) {
    const openvdb::Vec3d p = grid_.worldToIndex(openvdb::Vec3d(world[0], world[1], world[2]));
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return kNaN;
    const openvdb::Coord nearest(static_cast<openvdb::Int32>(std::lround(p[0])),
                                 static_cast<openvdb::Int32>(std::lround(p[1])),
                                 static_cast<openvdb::Int32>(std::lround(p[2])));
    if (nearest_ && !accessor_.isValueOn(nearest)) return kNaN;
    const openvdb::Coord base(static_cast<openvdb::Int32>(std::floor(p[0])),
                              static_cast<openvdb::Int32>(std::floor(p[1])),
                              static_cast<openvdb::Int32>(std::floor(p[2])));
    const double f[3] = {p[0] - base[0], p[1] - base[1], p[2] - base[2]};
    double sum = 0.0, weights = 0.0;
    for (int c = 0; c < 8; ++c) {
      const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
      const double w = (di ? f[0] : 1.0 - f[0]) * (dj ? f[1] : 1.0 - f[1]) * (dk ? f[2] : 1.0 - f[2]);
      float v = 0.0f;
      if (w > 0.0 && accessor_.probeValue(base.offsetBy(di, dj, dk), v)) {
        sum += w * static_cast<double>(v);
        weights += w;
      }
    }
    // NearestInactive: the nearest voxel is active and weighs at least 1/8, never 0 / 0.
    // AllInactive: no active corner with a weight is outside.
    return weights > 0.0 ? sum / weights : kNaN;
  }

 private:
  const openvdb::FloatGrid& grid_;
  openvdb::FloatGrid::ConstAccessor accessor_;
  bool nearest_;
};

// Either rule, or the stored values, behind one call.
class Sampler {
 public:
  Sampler(const openvdb::FloatGrid& grid, InactiveRule rule)
      : stored_(rule == InactiveRule::Stored), active_(grid, rule == InactiveRule::NearestInactive),
        sampler_(grid.constTree(), grid.transform()) {}
  double operator()(const std::array<double, 3>& world) {
    return stored_ ? sampler_.wsSample(openvdb::Vec3d(world[0], world[1], world[2])) : active_(world);
  }

 private:
  bool stored_;
  ActiveSampler active_;
  openvdb::tools::GridSampler<openvdb::FloatTree, openvdb::tools::BoxSampler> sampler_;
};

void gridRange(const openvdb::FloatGrid& grid, double& lo, double& hi) {
  if (grid.activeVoxelCount() == 0) {
    lo = hi = kNaN;
    return;
  }
  const openvdb::math::MinMax<float> mm = openvdb::tools::minMax(grid.tree());
  lo = mm.min();
  hi = mm.max();
}

}  // namespace

std::array<int, 2> slicePlaneAxes(int axis) {
  if (axis == 0) return {1, 2};
  if (axis == 1) return {0, 2};
  return {0, 1};
}

std::array<double, 3> GridSlice::position(int i, int j) const {
  std::array<double, 3> p{};
  p[static_cast<std::size_t>(axis)] = value;
  p[static_cast<std::size_t>(planeAxes[0])] = origin[0] + i * spacing[0];
  p[static_cast<std::size_t>(planeAxes[1])] = origin[1] + j * spacing[1];
  return p;
}

std::size_t GridSlice::finiteCount() const {
  return static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [](double v) { return std::isfinite(v); }));
}

GridSlice sampleGridSlice(const std::string& path, const GridSliceOptions& options) {
  if (options.axis < 0 || options.axis > 2)
    throw std::invalid_argument(path + ": slice axis " + std::to_string(options.axis) + ": expected 0 (x), 1 (y) or 2 (z)");
  if (!std::isfinite(options.value)) throw std::invalid_argument(path + ": the slice's position must be finite");
  if (options.samples < 0 || options.samples > kMaxSamples)
    throw std::invalid_argument(path + ": slice samples " + std::to_string(options.samples) + ": expected 0 to " +
                                std::to_string(kMaxSamples));
  if (options.window) {
    const auto& w = *options.window;
    const bool ok = std::all_of(w.begin(), w.end(), [](double x) { return std::isfinite(x); }) && w[1] > w[0] &&
                    w[3] > w[2];
    if (!ok) throw std::invalid_argument(path + ": the slice window must be finite with uMax > uMin and vMax > vMin");
  }
  const LoadedGrid loaded = loadGrid(path, options.grid);
  const openvdb::FloatGrid& grid = *loaded.grid;

  GridSlice s;
  s.header = loaded.header;
  s.axis = options.axis;
  s.value = options.value;
  s.planeAxes = slicePlaneAxes(options.axis);
  std::array<double, 4> w{};
  if (options.window) {
    w = *options.window;
  } else {
    if (s.header.emptyBox())
      throw std::runtime_error(path + ": grid '" + options.grid + "' has no active voxel to slice");
    w = {s.header.lo[s.planeAxes[0]], s.header.hi[s.planeAxes[0]], s.header.lo[s.planeAxes[1]],
         s.header.hi[s.planeAxes[1]]};
  }
  // Square cells: the longer side gets `samples` (or one per voxel), the shorter as many whole
  // cells as come nearest, each side's spacing then stretched a little to fit exactly.
  const double width = w[1] - w[0], height = w[3] - w[2];
  const double a = s.header.voxelSize;
  const double longer = std::max(width, height);
  const double cell = options.samples > 0 ? longer / options.samples : a;
  auto count = [&](double extent) {
    return static_cast<int>(std::clamp(std::round(extent / cell), 1.0, static_cast<double>(kMaxSamples)));
  };
  s.nx = count(width);
  s.ny = count(height);
  s.spacing = {width / s.nx, height / s.ny};
  s.origin = {w[0] + 0.5 * s.spacing[0], w[2] + 0.5 * s.spacing[1]};
  s.values.assign(static_cast<std::size_t>(s.nx) * static_cast<std::size_t>(s.ny), kNaN);

  // Rows in parallel, one sampler (accessor) per thread: each sample is written once, from
  // the same inputs, so the slice does not depend on the thread count.
#pragma omp parallel
  {
    Sampler sample(grid, options.inactive);
#pragma omp for schedule(static)
    for (int j = 0; j < s.ny; ++j)
      for (int i = 0; i < s.nx; ++i)
        s.values[static_cast<std::size_t>(i) + static_cast<std::size_t>(s.nx) * static_cast<std::size_t>(j)] =
            sample(s.position(i, j));
  }
  gridRange(grid, s.minValue, s.maxValue);
  return s;
}

std::vector<double> sampleGridPoints(const std::string& path, const std::string& grid,
                                     std::span<const std::array<double, 3>> points, InactiveRule inactive) {
  const LoadedGrid loaded = loadGrid(path, grid);
  std::vector<double> out(points.size(), kNaN);
  const auto n = static_cast<std::ptrdiff_t>(points.size());
#pragma omp parallel
  {
    Sampler sampler(*loaded.grid, inactive);
#pragma omp for schedule(static)
    for (std::ptrdiff_t k = 0; k < n; ++k) out[static_cast<std::size_t>(k)] = sampler(points[static_cast<std::size_t>(k)]);
  }
  return out;
}

GridHeader readGridHeader(const std::string& path, const std::string& grid) {
  openvdb::io::File file(path);
  openFile(file, path);
  requireGrid(file, path, grid);
  const openvdb::MetaMap::Ptr fileMeta = file.getMetadata();
  const openvdb::GridBase::Ptr g = file.readGridMetadata(grid);
  file.close();
  return headerOf(*g, *fileMeta, std::nullopt);
}

std::vector<std::string> gridNames(const std::string& path) {
  openvdb::io::File file(path);
  openFile(file, path);
  std::vector<std::string> names = gridNamesIn(file);
  file.close();
  return names;
}

}  // namespace ejecta::fields
