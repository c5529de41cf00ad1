// Grid files sampled on planes and at points (fields/grid_slice.hpp) and iso-surfaces of fog
// grids (fields/surface_mesh.hpp's meshIsoSurfaceFile): a grid holding a known linear field
// comes back exactly (trilinear interpolation is exact for linear fields), NaN outside its
// active voxels, with its metadata; a fog ball meshed at half its density is the sphere; errors
// name the file and the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "fields/grid_set.hpp"
#include "fields/grid_slice.hpp"
#include "fields/surface_mesh.hpp"
#include "fields/vdb_grids.hpp"
#include "support/temp_dir_test.hpp"

namespace ejecta::fields {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

class SliceFiles : public test::TempDirTest {};

GridFileMeta meta(bool levelSet) {
  GridFileMeta m;
  m.scene = "unit";
  m.time = 2.5e-3;
  m.step = 7;
  m.levelSet = levelSet;
  return m;
}

// Blocks covering voxel indices [-n, n)^3 (n a multiple of 8).
SparseLattice cube(double voxel, int n, int channels) {
  SparseLattice lat(3, voxel, channels);
  for (int i = -n; i < n; i += 8)
    for (int j = -n; j < n; j += 8)
      for (int k = -n; k < n; k += 8) lat.addBlock({i, j, k});
  return lat;
}

template <class F>
void forEachVoxel(const SparseLattice& lat, F f) {
  for (std::size_t b = 0; b < lat.blockCount(); ++b) {
    const Index3& o = lat.blockOrigin(b);
    for (int lx = 0; lx < 8; ++lx)
      for (int ly = 0; ly < 8; ++ly)
        for (int lz = 0; lz < 8; ++lz) f(b, lat.localIndex(lx, ly, lz), o[0] + lx, o[1] + ly, o[2] + lz);
  }
}

// The known grid: T = 300 + 4x + 8y - 2z [K] on voxels of a = 0.25 m, so that at voxel centres
// T = 300 + i + 2j - 0.5k, exact in single precision; active inside the ball i^2 + j^2 + k^2 <=
// 12^2 (off-centre by one voxel in x, so that the box is not symmetric), inactive elsewhere.
constexpr double kVoxel = 0.25;
constexpr int kBall = 12;
double linearT(double x, double y, double z) { return 300.0 + 4.0 * x + 8.0 * y - 2.0 * z; }
bool inBall(int i, int j, int k) { return (i - 1) * (i - 1) + j * j + k * k <= kBall * kBall; }

std::string writeLinear(const std::string& file) {
  GridSet set;
  set.lattice = cube(kVoxel, 16, 2);
  set.grids = {{"temperature", "K", 1, false}};
  set.source = Geometry::Spatial;
  forEachVoxel(set.lattice, [&](std::size_t b, int v, int i, int j, int k) {
    if (!inBall(i, j, k)) return;
    set.lattice.data(b, 0)[v] = 1.0f;  // any positive filled fraction marks the voxel active
    set.lattice.data(b, 1)[v] = static_cast<float>(linearT(i * kVoxel, j * kVoxel, k * kVoxel));
  });
  writeGridFile(file, set, meta(false));
  return file;
}

// Index coordinates of a world point and the two tests of the sampling rule: the nearest voxel,
// and all 8 voxels around it.
struct Where {
  bool nearestActive, allActive, anyActive;
};
Where where(const std::array<double, 3>& p) {
  const double u[3] = {p[0] / kVoxel, p[1] / kVoxel, p[2] / kVoxel};
  const int n[3] = {static_cast<int>(std::lround(u[0])), static_cast<int>(std::lround(u[1])),
                    static_cast<int>(std::lround(u[2]))};
  const int f[3] = {static_cast<int>(std::floor(u[0])), static_cast<int>(std::floor(u[1])),
                    static_cast<int>(std::floor(u[2]))};
  bool all = true, any = false;
  for (int c = 0; c < 8; ++c) {
    const bool in = inBall(f[0] + (c & 1), f[1] + ((c >> 1) & 1), f[2] + ((c >> 2) & 1));
    all = all && in;
    any = any || in;
  }
  return {inBall(n[0], n[1], n[2]), all, any};
}

TEST_F(SliceFiles, LinearFieldComesBackExactlyOnEveryAxisWithNaNOutside) {
  const std::string file = writeLinear(path("linear.vdb"));
  // The grid's range: its extreme active voxels, i + 2j - 0.5k over the ball.
  double lo = 1e300, hi = -1e300;
  for (int i = -16; i < 16; ++i)
    for (int j = -16; j < 16; ++j)
      for (int k = -16; k < 16; ++k)
        if (inBall(i, j, k)) {
          lo = std::min(lo, linearT(i * kVoxel, j * kVoxel, k * kVoxel));
          hi = std::max(hi, linearT(i * kVoxel, j * kVoxel, k * kVoxel));
        }
  // Planes between voxel centres (index 0.4 and -2.7), through the ball.
  for (int axis = 0; axis < 3; ++axis)
    for (double value : {0.1, -0.675}) {
      GridSliceOptions o;
      o.grid = "temperature";
      o.axis = axis;
      o.value = value;
      const GridSlice s = sampleGridSlice(file, o);
      const std::array<int, 2> uv = slicePlaneAxes(axis);
      EXPECT_EQ(s.planeAxes, uv);
      EXPECT_NE(uv[0], axis);
      EXPECT_NE(uv[1], axis);
      EXPECT_LT(uv[0], uv[1]);
      // No window: the active box in the plane to the voxels' outer faces, one sample per voxel,
      // centred on the voxel centres. The ball spans i in [-11, 13], j and k in [-12, 12].
      const int loIndex[3] = {-11, -12, -12}, hiIndex[3] = {13, 12, 12};
      EXPECT_EQ(s.nx, hiIndex[uv[0]] - loIndex[uv[0]] + 1);
      EXPECT_EQ(s.ny, hiIndex[uv[1]] - loIndex[uv[1]] + 1);
      EXPECT_DOUBLE_EQ(s.spacing[0], kVoxel);
      EXPECT_DOUBLE_EQ(s.spacing[1], kVoxel);
      EXPECT_NEAR(s.origin[0], loIndex[uv[0]] * kVoxel, 1e-12);
      EXPECT_NEAR(s.origin[1], loIndex[uv[1]] * kVoxel, 1e-12);
      EXPECT_EQ(s.header.units, "K");
      EXPECT_EQ(s.header.gridClass, "fog volume");
      EXPECT_EQ(s.header.scene, "unit");
      EXPECT_EQ(s.header.sourceGeometry, "3d");
      EXPECT_DOUBLE_EQ(s.header.time, 2.5e-3);
      EXPECT_EQ(s.header.step, 7);
      EXPECT_DOUBLE_EQ(s.minValue, lo);
      EXPECT_DOUBLE_EQ(s.maxValue, hi);
      std::size_t exact = 0, edge = 0, outside = 0;
      for (int j = 0; j < s.ny; ++j)
        for (int i = 0; i < s.nx; ++i) {
          const auto p = s.position(i, j);
          ASSERT_DOUBLE_EQ(p[static_cast<std::size_t>(axis)], value);
          const double v = s.values[static_cast<std::size_t>(i + s.nx * j)];
          const Where w = where(p);
          if (!w.nearestActive) {
            ASSERT_TRUE(std::isnan(v)) << "axis " << axis << " sample " << i << "," << j;
            ++outside;
          } else if (w.allActive) {
            // Voxel values exact in float, trilinear exact for a linear field: only double
            // round-off (~1e-13 on 300) remains.
            ASSERT_NEAR(v, linearT(p[0], p[1], p[2]), 1e-9) << "axis " << axis << " sample " << i << "," << j;
            ++exact;
          } else {
            // The edge: active corners only, renormalised, so a value between their extremes.
            ASSERT_TRUE(std::isfinite(v));
            ASSERT_GE(v, lo);
            ASSERT_LE(v, hi);
            ++edge;
          }
        }
      EXPECT_GT(exact, 300u);
      EXPECT_GT(outside, 50u);
      EXPECT_EQ(s.finiteCount(), exact + edge);
    }
}

TEST_F(SliceFiles, WindowsSamplesPointsAndStoredValues) {
  const std::string file = writeLinear(path("linear.vdb"));
  // A window wider than the ball, 200 samples along its longer side: square cells, centres
  // at window edge + (i + 1/2) spacing.
  GridSliceOptions o;
  o.grid = "temperature";
  o.value = 0.3;
  o.window = std::array<double, 4>{-4.0, 4.0, -2.0, 3.0};
  o.samples = 200;
  const GridSlice s = sampleGridSlice(file, o);
  EXPECT_EQ(s.nx, 200);
  EXPECT_EQ(s.ny, 125);
  EXPECT_DOUBLE_EQ(s.spacing[0], 0.04);
  EXPECT_DOUBLE_EQ(s.spacing[1], 0.04);
  EXPECT_NEAR(s.origin[0], -3.98, 1e-12);
  EXPECT_NEAR(s.origin[1], -1.98, 1e-12);
  std::size_t checked = 0;
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      const auto p = s.position(i, j);
      const double v = s.values[static_cast<std::size_t>(i + s.nx * j)];
      const Where w = where(p);
      if (!w.nearestActive) {
        ASSERT_TRUE(std::isnan(v));
      }
      if (w.allActive) {
        ASSERT_NEAR(v, linearT(p[0], p[1], p[2]), 1e-9);
        ++checked;
      }
    }
  EXPECT_GT(checked, 5000u);
  // The corners of the window lie far outside the ball.
  EXPECT_TRUE(std::isnan(s.values.front()));
  EXPECT_TRUE(std::isnan(s.values.back()));

  // Points anywhere: the same rule.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-3.6, 3.6);
  std::vector<std::array<double, 3>> points(2000);
  for (auto& p : points) p = {coord(rng), coord(rng), coord(rng)};
  const std::vector<double> values = sampleGridPoints(file, "temperature", points);
  ASSERT_EQ(values.size(), points.size());
  std::size_t inside = 0, nan = 0;
  for (std::size_t n = 0; n < points.size(); ++n) {
    const Where w = where(points[n]);
    if (!w.nearestActive) {
      EXPECT_TRUE(std::isnan(values[n]));
      ++nan;
    } else if (w.allActive) {
      EXPECT_NEAR(values[n], linearT(points[n][0], points[n][1], points[n][2]), 1e-9);
      ++inside;
    }
  }
  EXPECT_GT(inside, 100u);
  EXPECT_GT(nan, 100u);

  // AllInactive reaches a voxel further: NaN only where no voxel around is active; where the
  // nearest is inactive but another is not, the active ones' values (between the extremes).
  const std::vector<double> reach = sampleGridPoints(file, "temperature", points, InactiveRule::AllInactive);
  std::size_t beyond = 0;
  for (std::size_t n = 0; n < points.size(); ++n) {
    const Where w = where(points[n]);
    if (!w.anyActive) {
      EXPECT_TRUE(std::isnan(reach[n]));
    } else if (w.nearestActive) {
      EXPECT_EQ(reach[n], values[n]);
    } else {
      EXPECT_TRUE(std::isfinite(reach[n]));
      EXPECT_GE(reach[n], 300.0 - 4.0 * 3.6 - 8.0 * 3.6 - 2.0 * 3.6);
      EXPECT_LE(reach[n], 300.0 + 4.0 * 3.6 + 8.0 * 3.6 + 2.0 * 3.6);
      ++beyond;
    }
  }
  EXPECT_GT(beyond, 10u);

  // Stored values (OpenVDB's own trilinear sampler): the same inside, the background (0) far
  // outside, no NaN anywhere.
  o.inactive = InactiveRule::Stored;
  const GridSlice stored = sampleGridSlice(file, o);
  EXPECT_EQ(stored.finiteCount(), stored.values.size());
  EXPECT_EQ(stored.values.front(), 0.0);
  for (std::size_t k = 0; k < s.values.size(); ++k) {
    const Where w = where(s.position(static_cast<int>(k % 200), static_cast<int>(k / 200)));
    if (w.allActive) {
      EXPECT_NEAR(stored.values[k], s.values[k], 1e-4);  // OpenVDB interpolates in float
    }
  }
}

TEST_F(SliceFiles, HeadersNamesAndErrorsNamingFileAndGrid) {
  const std::string file = writeLinear(path("linear.vdb"));
  // The header's box from OpenVDB's file metadata, without the voxels, equals the box of the
  // loaded grid.
  const GridHeader h = readGridHeader(file, "temperature");
  GridSliceOptions o;
  o.grid = "temperature";
  const GridSlice s = sampleGridSlice(file, o);
  for (int d = 0; d < 3; ++d) {
    EXPECT_DOUBLE_EQ(h.lo[d], s.header.lo[d]);
    EXPECT_DOUBLE_EQ(h.hi[d], s.header.hi[d]);
  }
  EXPECT_DOUBLE_EQ(h.lo[0], -11.5 * kVoxel);
  EXPECT_DOUBLE_EQ(h.hi[0], 13.5 * kVoxel);
  EXPECT_EQ(h.units, "K");
  EXPECT_DOUBLE_EQ(h.voxelSize, kVoxel);
  EXPECT_FALSE(h.levelSet());
  EXPECT_FALSE(h.targetDensity.has_value());  // not an impact run's file
  EXPECT_EQ(gridNames(file), std::vector<std::string>{"temperature"});

  auto expectMessage = [&](auto call, const std::vector<std::string>& parts) {
    try {
      call();
      ADD_FAILURE() << "no exception; expected one naming " << parts.front();
    } catch (const std::exception& e) {
      for (const std::string& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
  };
  GridSliceOptions missing;
  missing.grid = "pressure";
  expectMessage([&] { sampleGridSlice(file, missing); }, {file, "'pressure'", "temperature"});
  expectMessage([&] { sampleGridPoints(file, "density", std::vector<std::array<double, 3>>{}); }, {file, "'density'"});
  expectMessage([&] { readGridHeader(file, "surface"); }, {file, "'surface'"});
  expectMessage([&] { sampleGridSlice(path("nothing.vdb"), o); }, {path("nothing.vdb")});
  expectMessage([&] { gridNames(path("nothing.vdb")); }, {path("nothing.vdb")});
  GridSliceOptions axis = o;
  axis.axis = 3;
  EXPECT_THROW(sampleGridSlice(file, axis), std::invalid_argument);
  GridSliceOptions window = o;
  window.window = std::array<double, 4>{1.0, -1.0, 0.0, 1.0};
  EXPECT_THROW(sampleGridSlice(file, window), std::invalid_argument);
  GridSliceOptions samples = o;
  samples.samples = -1;
  EXPECT_THROW(sampleGridSlice(file, samples), std::invalid_argument);
  GridSliceOptions nan = o;
  nan.value = std::nan("");
  EXPECT_THROW(sampleGridSlice(file, nan), std::invalid_argument);

  // A grid with no active voxel has no box to slice: said, naming it; with a window it is all NaN.
  GridSet empty;
  empty.lattice = cube(kVoxel, 8, 2);
  empty.grids = {{"damage", "1", 1, false}};
  empty.source = Geometry::Spatial;
  writeGridFile(path("empty.vdb"), empty, meta(false));
  GridSliceOptions damage;
  damage.grid = "damage";
  expectMessage([&] { sampleGridSlice(path("empty.vdb"), damage); }, {path("empty.vdb"), "'damage'", "no active voxel"});
  damage.window = std::array<double, 4>{-1.0, 1.0, -1.0, 1.0};
  const GridSlice none = sampleGridSlice(path("empty.vdb"), damage);
  EXPECT_EQ(none.finiteCount(), 0u);
  EXPECT_TRUE(std::isnan(none.minValue));
}

// A fog ball of radius R about the origin: S = 0.5 - (r - R)/w clamped to [0, 1] with w = 2
// voxels (an SPH free surface's smear), density 2680 S, so that half the density is the sphere
// r = R. Written with its level set.
std::string writeFogBall(const std::string& file, double voxel, double R) {
  const int n = 8 * static_cast<int>(std::ceil((R / voxel + 6.0) / 8.0));
  GridSet set;
  set.lattice = cube(voxel, n, 2);
  set.grids = {{"density", "kg/m^3", 1, false}};
  set.source = Geometry::Spatial;
  const double w = 2.0 * voxel;
  forEachVoxel(set.lattice, [&](std::size_t b, int v, int i, int j, int k) {
    const double r = voxel * std::sqrt(double(i) * i + double(j) * j + double(k) * k);
    const double S = std::clamp(0.5 - (r - R) / w, 0.0, 1.0);
    set.lattice.data(b, 0)[v] = static_cast<float>(S);
    set.lattice.data(b, 1)[v] = static_cast<float>(2680.0 * S);
  });
  writeGridFile(file, set, meta(true));
  return file;
}

TEST_F(SliceFiles, FogIsoSurfaceIsTheSphereFacingOutwards) {
  const double R = 1.234;
  double areaError[2];
  for (int level = 0; level < 2; ++level) {
    const double a = 0.1 / (1 << level);
    const std::string file = writeFogBall(path("fog" + std::to_string(level) + ".vdb"), a, R);
    SurfaceMeshOptions o;
    o.grid = "density";
    o.isovalue = 1340.0;
    const SurfaceMesh m = meshIsoSurfaceFile(file, o);
    ASSERT_FALSE(m.empty());
    areaError[level] = m.area() / (4.0 * kPi * R * R) - 1.0;
    const double volumeError = m.enclosedVolume() / (4.0 / 3.0 * kPi * R * R * R) - 1.0;
    const double q = (a / R) * (a / R);
    std::printf("fog ball R = %.1f voxels: %zu triangles, area error %+.3e = %+.3f (a/R)^2, volume error %+.3e\n",
                R / a, m.size(), areaError[level], areaError[level] / q, volumeError);
    // The fog is linear in r between voxel centres only along the axes; its trilinear
    // interpolation and volumeToMesh's flat quads cut inside the curved surface by O(a^2/R), as
    // for the level set (tests/fields/test_fields_surface.cpp). Bounds: 1.5 and 2.5 (a/R)^2.
    EXPECT_LT(std::abs(areaError[level]), 1.5 * q);
    EXPECT_LT(std::abs(volumeError), 2.5 * q);
    // Outwards: every triangle's right-hand normal points away from the centre.
    std::size_t inward = 0;
    for (const auto& t : m.triangles) {
      const auto& p0 = m.vertices[t[0]];
      const auto& p1 = m.vertices[t[1]];
      const auto& p2 = m.vertices[t[2]];
      const std::array<double, 3> e1{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const std::array<double, 3> e2{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
      const std::array<double, 3> nrm{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                      e1[0] * e2[1] - e1[1] * e2[0]};
      inward += (p0[0] + p1[0] + p2[0]) * nrm[0] + (p0[1] + p1[1] + p2[1]) * nrm[1] + (p0[2] + p1[2] + p2[2]) * nrm[2] <= 0.0;
    }
    EXPECT_EQ(inward, 0u);

    // The level set through meshIsoSurfaceFile is meshSurfaceFile's mesh, triangle for triangle.
    const SurfaceMesh viaIso = meshIsoSurfaceFile(file, SurfaceMeshOptions{});
    const SurfaceMesh viaSurface = meshSurfaceFile(file);
    EXPECT_EQ(viaIso.vertices, viaSurface.vertices);
    EXPECT_EQ(viaIso.triangles, viaSurface.triangles);

    if (level == 0) {
      // An isovalue at or below the background cannot close; beyond the values, no surface.
      o.isovalue = 0.0;
      EXPECT_THROW(meshIsoSurfaceFile(file, o), std::invalid_argument);
      o.isovalue = 5000.0;
      EXPECT_TRUE(meshIsoSurfaceFile(file, o).empty());
      o.grid = "temperature";
      EXPECT_THROW(meshIsoSurfaceFile(file, o), std::runtime_error);
    }
  }
  // Second order, as the level set's.
  EXPECT_NEAR(std::log2(areaError[0] / areaError[1]), 2.0, 0.3);
}

}  // namespace
}  // namespace ejecta::fields
