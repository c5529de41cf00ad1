// Pictures of grid files through the command line (coupling/grid_images.hpp behind `ejecta render
// FILE.vdb` and `ejecta run`'s [images] grids and surface), checked for what must be true of
// them: a slice of a step field shows its two colours on the right sides of the step and
// nothing where the grid is inactive; an iso-surface of a sphere is a disc of the radius the
// camera's projection gives, and cut open it shows the colour grid on the cut; a run draws the
// pictures of its grid files at their cadence; bad [images] keys are refused before the run.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <string>

#include "fields/grid_set.hpp"
#include "fields/vdb_grids.hpp"
#include "render/color_map.hpp"
#include "render/png_io.hpp"
#include "support/command_line.hpp"
#include "support/tiny_impact.hpp"
#include "support/temp_dir_test.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::runCommand;
using ejecta::test::readTextFile;
using ejecta::test::writeTextFile;

using ejecta::render::Image;
using ejecta::render::Rgba8;

// The number after `label` in the command's report (e.g. "px/m" -> the number before it).
double reported(const std::string& output, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(output, m, std::regex(pattern))) {
    ADD_FAILURE() << "no '" << pattern << "' in: " << output;
    return 0.0;
  }
  return std::stod(m[1].str());
}

struct Report {
  double pixelsPerMetre = 0.0, cameraDistance = 0.0;
  int width = 0, height = 0;  // the picture without the strip
};
Report parseReport(const std::string& output, bool perspective) {
  Report r;
  r.pixelsPerMetre = reported(output, R"(([0-9.e+-]+) px/m)");
  r.width = static_cast<int>(reported(output, R"(picture (\d+) x \d+ px)"));
  r.height = static_cast<int>(reported(output, R"(picture \d+ x (\d+) px)"));
  if (perspective) r.cameraDistance = reported(output, R"(camera ([0-9.e+-]+) m from)");
  return r;
}

Rgba8 mapColour(ejecta::render::ColorMapName name, double t) {
  return ejecta::render::toRgba8(ejecta::render::ColorMap(name).at(t));
}

bool near(const Rgba8& a, const Rgba8& b, int tolerance) {
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance && std::abs(a.b - b.b) <= tolerance;
}
bool white(const Rgba8& c) { return c.r == 255 && c.g == 255 && c.b == 255; }

std::string describe(const Rgba8& c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

class RenderGrids : public ejecta::test::TempDirTest {};

ejecta::fields::GridFileMeta meta(bool levelSet) {
  ejecta::fields::GridFileMeta m;
  m.scene = "picture";
  m.time = 1.25e-3;
  m.levelSet = levelSet;
  return m;
}

// Voxels of a = 0.1 m, i in [-16, 16), j and k in [-8, 8): density 1000 kg/m^3 for i < 0, 2000
// at i = 0, 3000 for i > 0, so that the step is centred on x = 0. A notch, i < -8 and j >= 4,
// is inactive.
constexpr double kStepVoxel = 0.1;
bool stepActive(int i, int j) { return !(i < -8 && j >= 4); }

fs::path writeStep(const fs::path& file) {
  ejecta::fields::GridSet set;
  set.lattice = ejecta::fields::SparseLattice(3, kStepVoxel, 2);
  for (int i = -16; i < 16; i += 8)
    for (int j = -8; j < 8; j += 8)
      for (int k = -8; k < 8; k += 8) set.lattice.addBlock({i, j, k});
  set.grids = {{"density", "kg/m^3", 1, false}};
  set.source = ejecta::Geometry::Spatial;
  for (std::size_t b = 0; b < set.lattice.blockCount(); ++b) {
    const auto& o = set.lattice.blockOrigin(b);
    for (int lx = 0; lx < 8; ++lx)
      for (int ly = 0; ly < 8; ++ly)
        for (int lz = 0; lz < 8; ++lz) {
          const int i = o[0] + lx, j = o[1] + ly, v = set.lattice.localIndex(lx, ly, lz);
          if (!stepActive(i, j)) continue;
          set.lattice.data(b, 0)[v] = 1.0f;
          set.lattice.data(b, 1)[v] = i < 0 ? 1000.0f : i == 0 ? 2000.0f : 3000.0f;
        }
  }
  ejecta::fields::writeGridFile(file.string(), set, meta(false));
  return file;
}

TEST_F(RenderGrids, StepSliceShowsItsTwoColoursOnTheirSides) {
  const fs::path file = writeStep(dir_ / "step.vdb");
  const fs::path png = dir_ / "step.png";
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " render " + file.string() + " --grid density --slice z --size 320 --out " + png.string(), out), 0)
      << out;
  EXPECT_NE(out.find("density on z = 0 m"), std::string::npos) << out;
  EXPECT_NE(out.find("colours 1000 to 3000 kg/m^3"), std::string::npos) << out;  // the grid's range
  const Report r = parseReport(out, false);
  const Image image = ejecta::render::readPng(png);
  ASSERT_EQ(image.width(), 320);
  ASSERT_EQ(r.width, 320);
  // The plane view centres the slice's box, x in [-1.65, 1.55] m and y in [-0.85, 0.75] m (the
  // voxels' outer faces), and fits its width with 3% to spare on each side.
  const double cx = -0.05, cy = -0.05;
  EXPECT_NEAR(r.pixelsPerMetre, 320.0 / (3.2 * 1.06), 1e-3);
  auto pixel = [&](double x, double y) {
    const int px = static_cast<int>(std::floor(r.width / 2.0 + (x - cx) * r.pixelsPerMetre));
    const int py = static_cast<int>(std::floor(r.height / 2.0 - (y - cy) * r.pixelsPerMetre));
    return image.at(px, py);
  };
  const Rgba8 low = mapColour(ejecta::render::ColorMapName::Viridis, 0.0);
  const Rgba8 high = mapColour(ejecta::render::ColorMapName::Viridis, 1.0);
  // Cells are their scale's exact colours: low for x < -0.1 m (beyond the interpolated step),
  // high for x > 0.1 m, at every height, on both sides of the step; 2000 between.
  int checked = 0;
  for (double y : {-0.8, -0.4, 0.0, 0.3, 0.7}) {
    for (double x : {-1.6, -1.0, -0.5, -0.15}) {
      if (x < -0.85 && y > 0.35) continue;  // the notch
      EXPECT_TRUE(near(pixel(x, y), low, 1)) << x << ", " << y << ": " << describe(pixel(x, y));
      ++checked;
    }
    for (double x : {0.15, 0.5, 1.0, 1.5}) {
      EXPECT_TRUE(near(pixel(x, y), high, 1)) << x << ", " << y << ": " << describe(pixel(x, y));
      ++checked;
    }
    // On the step itself, samples 0.01 m either side of x = 0: 1800 or 2200 kg/m^3, between.
    EXPECT_FALSE(near(pixel(0.0, y), low, 10) || near(pixel(0.0, y), high, 10)) << describe(pixel(0.0, y));
  }
  EXPECT_EQ(checked, 38);
  // Inactive voxels are transparent (the white page): the notch, and beyond the slice's edges.
  EXPECT_TRUE(white(pixel(-1.3, 0.6))) << describe(pixel(-1.3, 0.6));
  EXPECT_TRUE(white(pixel(-0.9, 0.6))) << describe(pixel(-0.9, 0.6));
  EXPECT_TRUE(white(pixel(-1.7, 0.0)));
  EXPECT_TRUE(white(pixel(1.6, 0.0)));
  EXPECT_TRUE(white(pixel(0.5, 0.8)));
  EXPECT_TRUE(white(pixel(0.5, -0.9)));
  EXPECT_TRUE(near(pixel(-0.8, 0.6), low, 1)) << describe(pixel(-0.8, 0.6));  // just right of the notch

  // A log scale has the same ends here (the grid's maximum, the slice's smallest positive
  // value): the same two colours on the same sides.
  ASSERT_EQ(runCommand(kEjecta + " render " + file.string() + " --grid density --log --size 320 --out " + png.string(), out), 0) << out;
  const Image logImage = ejecta::render::readPng(png);
  for (double y : {-0.4, 0.3}) {
    EXPECT_TRUE(near(logImage.at(static_cast<int>(r.width / 2.0 + (-1.0 - cx) * r.pixelsPerMetre),
                                 static_cast<int>(r.height / 2.0 - (y - cy) * r.pixelsPerMetre)),
                     low, 1));
    EXPECT_TRUE(near(logImage.at(static_cast<int>(r.width / 2.0 + (1.0 - cx) * r.pixelsPerMetre),
                                 static_cast<int>(r.height / 2.0 - (y - cy) * r.pixelsPerMetre)),
                     high, 1));
  }

  // Errors name the file and the grid, or the option.
  EXPECT_NE(runCommand(kEjecta + " render " + file.string() + " --grid pressure --out " + png.string(), out), 0);
  EXPECT_NE(out.find(file.string()), std::string::npos) << out;
  EXPECT_NE(out.find("'pressure'"), std::string::npos) << out;
  EXPECT_NE(runCommand(kEjecta + " render " + file.string() + " --slice w=1 --out " + png.string(), out), 0);
  EXPECT_NE(out.find("--slice 'w=1'"), std::string::npos) << out;
  EXPECT_NE(runCommand(kEjecta + " render " + file.string() + " --iso density --out " + png.string(), out), 0);
  EXPECT_NE(out.find("no reference density"), std::string::npos) << out;
}

// A fog ball of radius R at the origin (S = 0.5 - (r - R)/w clamped, w = 2 voxels; density 2680
// S), with its level set: both the density's half-density iso-surface and the level set's zero
// are the sphere r = R.
constexpr double kBallRadius = 1.0;

fs::path writeBall(const fs::path& file) {
  const double a = 0.05;
  const int n = 32;
  ejecta::fields::GridSet set;
  set.lattice = ejecta::fields::SparseLattice(3, a, 2);
  for (int i = -n; i < n; i += 8)
    for (int j = -n; j < n; j += 8)
      for (int k = -n; k < n; k += 8) set.lattice.addBlock({i, j, k});
  set.grids = {{"density", "kg/m^3", 1, false}};
  set.source = ejecta::Geometry::Spatial;
  for (std::size_t b = 0; b < set.lattice.blockCount(); ++b) {
    const auto& o = set.lattice.blockOrigin(b);
    for (int lx = 0; lx < 8; ++lx)
      for (int ly = 0; ly < 8; ++ly)
        for (int lz = 0; lz < 8; ++lz) {
          const double r = a * std::hypot(o[0] + lx, o[1] + ly, o[2] + lz);
          const double S = std::clamp(0.5 - (r - kBallRadius) / (2.0 * a), 0.0, 1.0);
          const int v = set.lattice.localIndex(lx, ly, lz);
          set.lattice.data(b, 0)[v] = static_cast<float>(S);
          set.lattice.data(b, 1)[v] = static_cast<float>(2680.0 * S);
        }
  }
  ejecta::fields::writeGridFile(file.string(), set, meta(true));
  return file;
}

// The disc of non-white pixels in the picture: its area's radius and its centroid.
struct Disc {
  double radius = 0.0, cx = 0.0, cy = 0.0;
};
Disc measureDisc(const Image& image, int plotHeight) {
  double n = 0.0, sx = 0.0, sy = 0.0;
  for (int y = 0; y < plotHeight; ++y)
    for (int x = 0; x < image.width(); ++x)
      if (!white(image.at(x, y))) {
        n += 1.0;
        sx += x + 0.5;
        sy += y + 0.5;
      }
  return {std::sqrt(n / std::numbers::pi), n > 0 ? sx / n : 0.0, n > 0 ? sy / n : 0.0};
}

TEST_F(RenderGrids, SphereIsoSurfaceIsADiscOfTheProjectedRadius) {
  const fs::path file = writeBall(dir_ / "ball.vdb");
  const fs::path png = dir_ / "disc.png";
  // The density's iso-surface, and by default (no choice: the file has a surface level set)
  // the level set's zero: the same sphere.
  for (const std::string& choice : {std::string("--iso density=1340"), std::string("--iso 'density=1.34 g/cm^3'"),
                                    std::string("")}) {
    std::string out;
    ASSERT_EQ(runCommand(kEjecta + " render " + file.string() + " " + choice + " --cut none --size 400 --out " + png.string(), out), 0)
        << out;
    const Report r = parseReport(out, true);
    const Image image = ejecta::render::readPng(png);
    // A sphere of radius R seen from distance D fills a cone of half-angle asin(R/D); on the
    // image plane, f = (px/m at the target) D pixels from the eye, its edge is f tan(asin(R/D))
    // = f R / sqrt(D^2 - R^2) from the centre.
    const double D = r.cameraDistance, f = r.pixelsPerMetre * D;
    const double expected = f * kBallRadius / std::sqrt(D * D - kBallRadius * kBallRadius);
    const Disc disc = measureDisc(image, r.height);
    std::printf("%s: disc radius %.2f px (expected %.2f), centre (%.2f, %.2f) in a %d x %d picture\n",
                choice.empty() ? "default (surface level set)" : choice.c_str(), disc.radius, expected, disc.cx,
                disc.cy, r.width, r.height);
    // The mesh lies inside the sphere by O(a^2/R) (tests/fields/test_fields_slice.cpp: about 0.1% of R,
    // a quarter pixel here) and the disc's edge pixels are whole pixels: 1.5 px.
    EXPECT_NEAR(disc.radius, expected, 1.5) << out;
    EXPECT_GT(expected, 100.0);
    // Centred on the camera's target, the sphere's centre.
    EXPECT_NEAR(disc.cx, r.width / 2.0, 1.0);
    EXPECT_NEAR(disc.cy, r.height / 2.0, 1.0);
    const std::string level = choice.empty() ? "surface = 0 m" : "density = 1340 kg/m^3";
    EXPECT_NE(out.find(level), std::string::npos) << out;
  }

  // Cut open (z <= 0 kept, seen from +z) and coloured by density: the cut face shows the inside,
  // 2680 kg/m^3, the top of the scale (the surface's vertices hold half that), at the picture's
  // centre; the shell around it is coloured too, not grey.
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " render " + file.string() + " --iso density=1340 --color-by density --size 300 --out " +
                    png.string(), out), 0)
      << out;
  EXPECT_NE(out.find("cut at z = 0 m"), std::string::npos) << out;
  const Report r = parseReport(out, true);
  const Image image = ejecta::render::readPng(png);
  const Rgba8 centre = image.at(r.width / 2, r.height / 2);
  EXPECT_TRUE(near(centre, mapColour(ejecta::render::ColorMapName::Viridis, 1.0), 2)) << describe(centre);
  const double reach = 0.5 * r.pixelsPerMetre * kBallRadius;  // half-way out on the cut face
  const Rgba8 face = image.at(static_cast<int>(r.width / 2 - reach), r.height / 2);
  EXPECT_TRUE(near(face, centre, 2)) << describe(face);
  // The cut removed the near half: fewer pixels than the whole sphere, but more than none.
  const Disc cut = measureDisc(image, r.height);
  EXPECT_GT(cut.radius, 0.5 * r.pixelsPerMetre * kBallRadius);
}

TEST_F(RenderGrids, RunDrawsItsGridPicturesAndRefusesBadKeys) {
  ejecta::test::TinyImpact o;
  o.tEnd = "6 us";
  o.snapshotInterval = "6 us";
  o.extra = "[fields]\ngrids = [\"density\", \"temperature\", \"fractions\"]\n"
            "[images]\nfields = []\ngrids = [\"temperature\", \"fraction_granite\"]\nsurface = true\nsize = 256\n";
  writeTextFile(dir_ / "scene.toml", ejecta::test::tinyImpactScene(o));
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " run " + (dir_ / "scene.toml").string() + " --quiet --no-charts --threads 2 --out " +
                    (dir_ / "run").string(), out), 0)
      << out;
  EXPECT_EQ(out.find("warning"), std::string::npos) << out;
  const fs::path images = dir_ / "run" / "images";
  // Outputs 0 (t = 0) and 1 (t = 6 us), each with its grid file and its pictures, the body
  // drawn in the top half of each; no particle frames (fields = []).
  for (const char* name : {"grid_temperature_0000.png", "grid_temperature_0001.png", "grid_fraction_granite_0000.png",
                           "grid_fraction_granite_0001.png", "surface_0000.png", "surface_0001.png"}) {
    ASSERT_TRUE(fs::exists(images / name)) << name;
    const Image image = ejecta::render::readPng(images / name);
    EXPECT_EQ(image.width(), 256);
    int drawn = 0;
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 256; ++x) drawn += !white(image.at(x, y));
    EXPECT_GT(drawn, 3000) << name;
  }
  EXPECT_FALSE(fs::exists(images / "density_0000.png"));
  // At t = 0 the temperature is 293 K everywhere, up to float noise: one colour, the map's
  // middle (a uniform field is widened +-50%), on the slice and on the surface's cut face (drawn
  // unlit), not a ramp stretched over the noise.
  const Rgba8 middle = mapColour(ejecta::render::ColorMapName::Inferno, 0.5);
  for (const char* name : {"grid_temperature_0000.png", "surface_0000.png"}) {
    const Image image = ejecta::render::readPng(images / name);
    int uniform = 0, drawn = 0;
    for (int y = 0; y < 200; ++y)
      for (int x = 0; x < 256; ++x) {
        uniform += near(image.at(x, y), middle, 2);
        drawn += !white(image.at(x, y));
      }
    EXPECT_GT(uniform, 2000) << name;
    if (std::string(name).rfind("grid", 0) == 0) {
      EXPECT_GT(uniform, drawn * 9 / 10) << name;  // the slice is all one colour
    }
  }

  // The command on the run directory takes its last grid file.
  ASSERT_EQ(runCommand(kEjecta + " render " + (dir_ / "run").string() + " --grid temperature --out " +
                    (dir_ / "last.png").string(), out), 0)
      << out;
  EXPECT_NE(out.find("fields_0001.vdb"), std::string::npos) << out;

  // Names the run does not write, and a surface without grids, are refused before the run.
  o.extra = "[fields]\ngrids = [\"density\"]\n[images]\ngrids = [\"pressure\"]\n";
  writeTextFile(dir_ / "bad.toml", ejecta::test::tinyImpactScene(o));
  EXPECT_NE(runCommand(kEjecta + " run " + (dir_ / "bad.toml").string() + " --quiet --out " + (dir_ / "bad").string(), out), 0);
  EXPECT_NE(out.find("images.grids"), std::string::npos) << out;
  EXPECT_NE(out.find("'pressure' is not a grid the run writes"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir_ / "bad" / "summary.json"));
  o.extra = "[images]\nsurface = true\n";
  writeTextFile(dir_ / "bad2.toml", ejecta::test::tinyImpactScene(o));
  EXPECT_NE(runCommand(kEjecta + " run " + (dir_ / "bad2.toml").string() + " --quiet --out " + (dir_ / "bad2").string(), out), 0);
  EXPECT_NE(out.find("images.surface"), std::string::npos) << out;
}

}  // namespace
