// Grid files for the radiation code (fields/surface_mesh.hpp, fields/grid_voxels.hpp): a sphere's
// level set meshed by volumeToMesh against the sphere's exact area and volume (at the surface,
// moved inwards, and adaptively), and the hot voxels of a grid whose every value is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fields/grid_set.hpp"
#include "fields/grid_voxels.hpp"
#include "fields/surface_mesh.hpp"
#include "fields/vdb_grids.hpp"
#include "support/temp_dir_test.hpp"

namespace ejecta::fields {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

class SurfaceFiles : public test::TempDirTest {};

GridFileMeta meta() {
  GridFileMeta m;
  m.scene = "unit";
  m.time = 2.5e-3;
  m.step = 7;
  return m;
}

// Blocks covering voxel indices [-n, n)^3 (n a multiple of 8), `channels` zeroed channels.
SparseLattice cube(double voxel, int n, int channels) {
  SparseLattice lat(3, voxel, channels);
  for (int i = -n; i < n; i += 8)
    for (int j = -n; j < n; j += 8)
      for (int k = -n; k < n; k += 8) lat.addBlock({i, j, k});
  return lat;
}

// Calls f(block, local index, i, j, k) for every voxel of the lattice.
template <class F>
void forEachVoxel(const SparseLattice& lat, F f) {
  for (std::size_t b = 0; b < lat.blockCount(); ++b) {
    const Index3& o = lat.blockOrigin(b);
    for (int lx = 0; lx < 8; ++lx)
      for (int ly = 0; ly < 8; ++ly)
        for (int lz = 0; lz < 8; ++lz) f(b, lat.localIndex(lx, ly, lz), o[0] + lx, o[1] + ly, o[2] + lz);
  }
}

// A ball of radius R about the origin: filled fraction S = 0.5 - (r - R)/w clamped to [0, 1], a
// linear ramp of width w = 2 voxels as an SPH sum smears a free surface (docs/fields.md), so the
// level set's zero (S = 0.5) is the sphere r = R.
std::string writeBall(const std::string& file, double voxel, double R) {
  const int n = 8 * static_cast<int>(std::ceil((R / voxel + 6.0) / 8.0));
  GridSet set;
  set.lattice = cube(voxel, n, 1);
  set.grids = {{"density", "kg/m^3", 0, false}};
  set.source = Geometry::Spatial;
  const double w = 2.0 * voxel;
  forEachVoxel(set.lattice, [&](std::size_t b, int v, int i, int j, int k) {
    const double r = voxel * std::sqrt(double(i) * i + double(j) * j + double(k) * k);
    set.lattice.data(b, 0)[v] = static_cast<float>(std::clamp(0.5 - (r - R) / w, 0.0, 1.0));
  });
  writeGridFile(file, set, meta());
  return file;
}

TEST_F(SurfaceFiles, SphereLevelSetMeshesToTheSpheresAreaAndVolume) {
  // R = 12.34 voxels (not aligned with the lattice), then the voxel halved.
  const double R = 1.234;
  double areaError[2], volumeError[2];
  SurfaceMesh m;
  for (int level = 0; level < 2; ++level) {
    const double a = 0.1 / (1 << level);
    m = meshSurfaceFile(writeBall(path("ball" + std::to_string(level) + ".vdb"), a, R));
    ASSERT_FALSE(m.empty());
    EXPECT_DOUBLE_EQ(m.voxelSize, a);
    EXPECT_EQ(m.size(), 2 * m.quads);  // adaptivity 0: quads only, each split in two
    areaError[level] = m.area() / (4.0 * kPi * R * R) - 1.0;
    volumeError[level] = m.enclosedVolume() / (4.0 / 3.0 * kPi * R * R * R) - 1.0;
    const double q = (a / R) * (a / R);
    std::printf("sphere R = %.2f voxels: %zu triangles, area error %+.3e = %+.3f (a/R)^2, volume error %+.3e = "
                "%+.3f (a/R)^2\n",
                R / a, m.size(), areaError[level], areaError[level] / q, volumeError[level], volumeError[level] / q);
    // The surface comes out inside the sphere by a second-order amount: trilinear interpolation of
    // the fog (linear in r, which is convex) between voxel centres, the flat polygons of the level
    // set's rebuild, and volumeToMesh's own vertices (one per cell, inside the curved surface) and
    // flat quads each sag by O(a^2 / R). Measured: area -1.25 (a/R)^2, volume -2.05 (a/R)^2 at
    // R/a = 12.3, 24.7 and 49.4. Bounds: 1.5 and 2.5 (a/R)^2 (0.99% and 1.6% at R/a = 12.3).
    EXPECT_LT(std::abs(areaError[level]), 1.5 * q);
    EXPECT_LT(std::abs(volumeError[level]), 2.5 * q);
  }
  // Second order: halving the voxel quarters the error (order 2 +- 0.2).
  EXPECT_NEAR(std::log2(areaError[0] / areaError[1]), 2.0, 0.2);
  EXPECT_NEAR(std::log2(volumeError[0] / volumeError[1]), 2.0, 0.2);
  const double a = 0.05;  // the finer mesh, m, below

  // Outward orientation (counter-clockwise seen from outside, the radiation code's convention):
  // every triangle's right-hand normal points away from the centre.
  std::size_t inward = 0;
  for (const auto& t : m.triangles) {
    const auto& p0 = m.vertices[t[0]];
    const auto& p1 = m.vertices[t[1]];
    const auto& p2 = m.vertices[t[2]];
    const std::array<double, 3> e1{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const std::array<double, 3> e2{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const std::array<double, 3> nrm{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                    e1[0] * e2[1] - e1[1] * e2[0]};
    const double c = (p0[0] + p1[0] + p2[0]) * nrm[0] + (p0[1] + p1[1] + p2[1]) * nrm[1] +
                     (p0[2] + p1[2] + p2[2]) * nrm[2];
    inward += c <= 0.0;
  }
  EXPECT_EQ(inward, 0u);
  EXPECT_GT(m.enclosedVolume(), 0.0);
  // Every vertex lies within a tenth of a voxel of the sphere (measured 0.032 at R/a = 24.7: the
  // same O(a^2/R) shift).
  double worst = 0.0;
  for (const auto& v : m.vertices) worst = std::max(worst, std::abs(std::hypot(v[0], v[1], v[2]) - R));
  EXPECT_LT(worst, 0.1 * a);
  std::printf("largest vertex distance from the sphere: %.3f voxels\n", worst / a);
}

TEST_F(SurfaceFiles, InsetAndAdaptiveMeshes) {
  const double a = 0.1, R = 1.234;
  const std::string file = writeBall(path("ball.vdb"), a, R);
  // 1.5 voxels inwards: the sphere of radius r = R - 0.15 m, with the surface's error budget,
  // 1.5 (a/r)^2 = 1.3% on the area at r = 10.8 voxels.
  SurfaceMeshOptions inset;
  inset.isovalue = -0.15;
  const SurfaceMesh in = meshSurfaceFile(file, inset);
  const double r = R - 0.15;
  const double insetError = in.area() / (4.0 * kPi * r * r) - 1.0;
  EXPECT_LT(std::abs(insetError), 1.5 * (a / r) * (a / r));
  // Adaptive: merged polygons span several voxels and cut deeper chords. At 0.02, a quarter of the
  // triangles; measured -1.4% on the area (adaptivity 0.1: -4%, 0.5: -11%). Bound: 2.5%.
  SurfaceMeshOptions adaptive;
  adaptive.adaptivity = 0.02;
  const SurfaceMesh ad = meshSurfaceFile(file, adaptive);
  const SurfaceMesh full = meshSurfaceFile(file);
  const double adaptiveError = ad.area() / (4.0 * kPi * R * R) - 1.0;
  std::printf("inset 1.5 voxels: area error %+.3e; adaptivity 0.02: %zu triangles (%zu at 0), area error %+.3e\n",
              insetError, ad.size(), full.size(), adaptiveError);
  EXPECT_LT(ad.size(), full.size() / 2);
  EXPECT_LT(std::abs(adaptiveError), 0.025);
  EXPECT_GT(ad.enclosedVolume(), 0.0);

  // The narrow band is 3 voxels: an isovalue beyond 2 voxels is refused, naming the file.
  SurfaceMeshOptions deep;
  deep.isovalue = -0.25;
  try {
    meshSurfaceFile(file, deep);
    FAIL() << "an isovalue outside the narrow band was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("narrow band"), std::string::npos) << e.what();
  }
  SurfaceMeshOptions badAdaptivity;
  badAdaptivity.adaptivity = 1.5;
  EXPECT_THROW(meshSurfaceFile(file, badAdaptivity), std::invalid_argument);
  // A fog grid is not a level set; a missing grid or file is named.
  SurfaceMeshOptions fog;
  fog.grid = "density";
  EXPECT_THROW(meshSurfaceFile(file, fog), std::runtime_error);
  SurfaceMeshOptions missing;
  missing.grid = "surface_granite";
  try {
    meshSurfaceFile(file, missing);
    FAIL() << "a missing grid was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("surface_granite"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the file has: density"), std::string::npos) << e.what();
  }
  EXPECT_THROW(meshSurfaceFile(path("nothing.vdb")), std::runtime_error);
  EXPECT_EQ(gridVoxelSize(file).value_or(0.0), a);
  EXPECT_FALSE(gridVoxelSize(file, "surface_granite").has_value());
  EXPECT_FALSE(gridVoxelSize(path("nothing.vdb")).has_value());
}

// A known grid: temperature T = 1400 + 10 i + j [K] (integers: exact in float) at voxel
// (i, j, k); two fraction grids (filled fractions) f_rock = 0.25 + 0.01 (k + 16),
// f_iron = 0.125. Material everywhere in the lattice except where i + j + k is a multiple of 7
// (holes: inactive voxels).
struct KnownGrid {
  static double temperature(int i, int j, int /*k*/) { return 1400.0 + 10.0 * i + j; }
  static double rock(int, int, int k) { return 0.25 + 0.01 * (k + 16); }
  static bool filled(int i, int j, int k) { return ((i + j + k) % 7 + 7) % 7 != 0; }
};

std::string writeKnownGrid(const std::string& file, double voxel, bool shepardIron,
                           std::vector<std::string> runMaterials = {}) {
  GridSet set;
  set.materials = std::move(runMaterials);  // none: a file written before the material list
  set.lattice = cube(voxel, 16, 4);
  // channel 0: the filled fraction (any positive value marks a voxel active); 1: temperature as
  // a plain sum (stored as it is); 2, 3: the fractions, rock's tagged as runs write fractions
  // ("capped": divided by S only where S > 1; here S = 1), iron's a plain sum or Shepard's.
  set.grids = {{"temperature", "K", 1, false},
               {"fraction_rock", "1", 2, false, true},
               {"fraction_iron", "1", 3, shepardIron}};
  set.source = Geometry::Axisymmetric;
  forEachVoxel(set.lattice, [&](std::size_t b, int v, int i, int j, int k) {
    if (!KnownGrid::filled(i, j, k)) return;
    set.lattice.data(b, 0)[v] = 1.0f;
    set.lattice.data(b, 1)[v] = static_cast<float>(KnownGrid::temperature(i, j, k));
    set.lattice.data(b, 2)[v] = static_cast<float>(KnownGrid::rock(i, j, k));
    set.lattice.data(b, 3)[v] = 0.125f;
  });
  GridFileMeta m = meta();
  m.levelSet = false;
  writeGridFile(file, set, m);
  return file;
}

TEST_F(SurfaceFiles, HotVoxelsOfAKnownGrid) {
  const double a = 0.2;
  const std::string file = writeKnownGrid(path("known.vdb"), a, false);
  const GridVoxels v = readGridVoxels(file);  // temperature >= 1500 K
  // The expected set, voxel by voxel.
  std::size_t active = 0, hot = 0;
  for (int i = -16; i < 16; ++i)
    for (int j = -16; j < 16; ++j)
      for (int k = -16; k < 16; ++k) {
        if (!KnownGrid::filled(i, j, k)) continue;
        ++active;
        hot += KnownGrid::temperature(i, j, k) >= 1500.0;  // the threshold is inclusive
      }
  EXPECT_EQ(v.activeVoxels, active);
  ASSERT_EQ(v.size(), hot);
  ASSERT_GT(hot, 0u);
  EXPECT_DOUBLE_EQ(v.voxelSize, a);
  EXPECT_NEAR(v.voxelVolume, a * a * a, 1e-15);
  EXPECT_EQ(v.grid, "temperature");
  EXPECT_EQ(v.units, "K");
  EXPECT_EQ(v.sourceGeometry, "rz");
  EXPECT_DOUBLE_EQ(v.time, 2.5e-3);
  ASSERT_EQ(v.materials.size(), 2u);
  ASSERT_EQ(v.fraction.size(), 2u);
  EXPECT_TRUE(v.fractionsAreFill);  // "capped" and "none" are both filled fractions
  EXPECT_TRUE(v.missingFractions.empty());  // a file without the run's material list
  const auto rock = std::find(v.materials.begin(), v.materials.end(), "rock") - v.materials.begin();
  const auto iron = std::find(v.materials.begin(), v.materials.end(), "iron") - v.materials.begin();
  ASSERT_LT(rock, 2);
  ASSERT_LT(iron, 2);
  std::size_t exactBoundary = 0;
  for (std::size_t n = 0; n < v.size(); ++n) {
    // Centres are index x voxel (OpenVDB's cell-centred convention, docs/fields.md).
    const int i = static_cast<int>(std::lround(v.x[n] / a)), j = static_cast<int>(std::lround(v.y[n] / a)),
              k = static_cast<int>(std::lround(v.z[n] / a));
    ASSERT_NEAR(v.x[n], i * a, 1e-12);
    ASSERT_NEAR(v.y[n], j * a, 1e-12);
    ASSERT_NEAR(v.z[n], k * a, 1e-12);
    ASSERT_TRUE(KnownGrid::filled(i, j, k)) << i << " " << j << " " << k;
    ASSERT_EQ(v.value[n], KnownGrid::temperature(i, j, k));
    ASSERT_GE(v.value[n], 1500.0);
    EXPECT_EQ(v.fraction[rock][n], static_cast<double>(static_cast<float>(KnownGrid::rock(i, j, k))));
    EXPECT_EQ(v.fraction[iron][n], 0.125);
    exactBoundary += v.value[n] == 1500.0;
  }
  EXPECT_GT(exactBoundary, 0u);  // voxels at exactly the threshold are kept

  // A higher threshold keeps a subset; no fractions when not asked for.
  GridVoxelOptions o;
  o.threshold = 1550.0;
  o.fractions = false;
  const GridVoxels fewer = readGridVoxels(file, o);
  EXPECT_LT(fewer.size(), v.size());
  EXPECT_TRUE(fewer.materials.empty());
  EXPECT_FALSE(fewer.fractionsAreFill);
  for (double t : fewer.value) EXPECT_GE(t, 1550.0);

  // A Shepard-normalised fraction grid makes the fractions shares, not filled fractions.
  const GridVoxels shares = readGridVoxels(writeKnownGrid(path("shares.vdb"), a, true));
  EXPECT_FALSE(shares.fractionsAreFill);

  // Errors name the file and the grid.
  GridVoxelOptions missing;
  missing.grid = "pressure";
  try {
    readGridVoxels(file, missing);
    FAIL() << "a missing grid was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'pressure'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the file has: "), std::string::npos) << e.what();
  }
  EXPECT_THROW(readGridVoxels(path("nothing.vdb")), std::runtime_error);
  GridVoxelOptions nan;
  nan.threshold = std::nan("");
  EXPECT_THROW(readGridVoxels(file, nan), std::invalid_argument);
}

TEST_F(SurfaceFiles, MaterialsWithoutAFractionGridAreNamed) {
  // The file lists the run's materials; a run that wrote the fractions of some (rock, iron) but
  // not of another (ice) leaves ice's voxels looking empty: the reader names it.
  const GridVoxels some = readGridVoxels(writeKnownGrid(path("some.vdb"), 0.2, false, {"rock", "ice", "iron"}));
  EXPECT_EQ(some.missingFractions, std::vector<std::string>{"ice"});
  const GridVoxels all = readGridVoxels(writeKnownGrid(path("all.vdb"), 0.2, false, {"iron", "rock"}));
  EXPECT_TRUE(all.missingFractions.empty());
  // Without the fractions asked for, nothing is missing (each voxel is then taken as full).
  GridVoxelOptions bare;
  bare.fractions = false;
  EXPECT_TRUE(readGridVoxels(path("some.vdb"), bare).missingFractions.empty());
}

TEST_F(SurfaceFiles, AFractionOfAMaterialNotListedIsRefused) {
  // fraction_iron in a file whose run had rock and ice only: the file and the grid are named.
  const std::string file = writeKnownGrid(path("mixed.vdb"), 0.2, false, {"rock", "ice"});
  try {
    readGridVoxels(file);
    FAIL() << "a fraction grid of a material the file does not list was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mixed.vdb"), std::string::npos) << what;
    EXPECT_NE(what.find("'fraction_iron'"), std::string::npos) << what;
    EXPECT_NE(what.find("(rock, ice)"), std::string::npos) << what;
  }
  // Without the fractions asked for, the grid is read.
  GridVoxelOptions bare;
  bare.fractions = false;
  EXPECT_GT(readGridVoxels(file, bare).size(), 0u);
}

}  // namespace
}  // namespace ejecta::fields
