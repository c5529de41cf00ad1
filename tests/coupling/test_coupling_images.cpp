// The in-situ chain as a library (coupling/): a C++ user draws a run's pictures without the
// command line. These call coupling/ directly; the command-line tests (test_chain_*) go through
// the binary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <numbers>
#include <set>
#include <string>
#include <vector>
#include <cmath>

#include "coupling/category_images.hpp"
#include "coupling/particle_images.hpp"
#include "coupling/run_images.hpp"
#include "render/png_io.hpp"
#include "render/renderer.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/solid/materials.hpp"
#include "support/tiny_impact.hpp"

namespace fs = std::filesystem;
using namespace ejecta;

namespace {

fs::path tempDir(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_coupling_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Distinct colours in a picture: a blank or one-colour image has one or two.
std::size_t colours(const render::Image& image) {
  std::set<std::uint32_t> seen;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const render::Rgba8 c = image.at(x, y);
      seen.insert(static_cast<std::uint32_t>(c.r) << 16 | static_cast<std::uint32_t>(c.g) << 8 | c.b);
    }
  return seen.size();
}

}  // namespace

TEST(CouplingImages, DrawsTheParticlesOfABuiltScene) {
  const Scene scene = parseScene(test::tinyImpactScene(), "tiny.toml");
  const ParticleSet p = buildParticles(scene, MaterialTable::fromScene(scene));
  const fs::path dir = tempDir("particles");
  render::RenderSettings settings;
  settings.width = settings.height = 256;
  render::Renderer renderer(settings);
  coupling::ParticleImageOptions options;
  options.field = "density";
  coupling::writeParticleImage(renderer, p, scene.geometry, 0.0, scene.name, options, dir / "density.png");
  const render::Image image = render::readPng(dir / "density.png");
  EXPECT_EQ(image.width(), 256);
  // Two materials of different density, the background, the colour bar and the text.
  EXPECT_GT(colours(image), 8u);
  options.field = "no_such_field";
  EXPECT_THROW(coupling::writeParticleImage(renderer, p, scene.geometry, 0.0, scene.name, options,
                                            dir / "bad.png"),
               std::invalid_argument);
  fs::remove_all(dir);
}

TEST(CouplingImages, ARunThroughTheLibraryDrawsItsFrames) {
  test::TinyImpact o;
  o.tEnd = "20 us";
  o.snapshotInterval = "10 us";
  o.extra = "[images]\nfields = [\"density\", \"pressure\"]\nsize = 128\n";
  const std::string text = test::tinyImpactScene(o);
  const Scene scene = parseScene(text, "tiny.toml");
  const fs::path dir = tempDir("run");
  RunOptions options;
  options.outDir = dir.string();
  options.sceneSource = text;
  options.threads = 2;
  coupling::addImageOutputs(options, scene, /*charts=*/false);
  const RunOutcome r = runScene(scene, options);
  ASSERT_TRUE(r.ok) << r.error;
  for (const char* frame : {"density_0000.png", "density_0002.png", "pressure_0001.png"}) {
    EXPECT_TRUE(fs::exists(dir / "images" / frame)) << frame;
  }
  fs::remove_all(dir);
}

namespace {

// A square lattice of `n` x `n` particles at spacing `dx` (density 1), in the x-y plane.
ParticleSet lattice(int n, double dx, Geometry geometry) {
  ParticleSet p;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
      // Mass of the particle's cell: per unit depth in 2D, the ring in RZ.
      const double mass = geometry == Geometry::Axisymmetric ? 2.0 * std::numbers::pi * x * dx * dx : dx * dx;
      p.append({x, y, 0.0}, {0, 0, 0}, mass, 1.0, 1.0, 1.2 * dx, 0);
    }
  return p;
}

}  // namespace

TEST(CouplingImages, DiscsAreSizedToEachParticlesOwnSpacing) {
  for (const Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const ParticleSet p = lattice(6, 0.1, g);
    for (const double r : coupling::particleDiscRadii(p, g)) EXPECT_NEAR(r, 0.075, 1e-12);  // 0.75 dx
  }
}

TEST(CouplingImages, ALatticeDrawsWithoutGaps) {
  // The moire of earlier pictures: discs of h / 2 on a square lattice left the cells' centres
  // (0.707 of the spacing from the particles) unpainted. Flat discs sized to the spacing paint
  // every pixel of the body; RZ mirrored about the axis has no seam on it either.
  for (const Geometry g : {Geometry::Planar, Geometry::Axisymmetric}) {
    const ParticleSet p = lattice(40, 0.05, g);
    render::RenderSettings settings;
    settings.width = settings.height = 400;
    settings.background = {1.0f, 1.0f, 1.0f};
    render::Renderer renderer(settings);
    coupling::ParticleLayerArrays arrays;
    coupling::ParticleImageOptions options;
    options.field = "density";
    render::Picture scene;
    scene.particles.push_back(coupling::particleLayer(p, g, options, arrays));
    scene.particles.back().style = render::ParticleStyle::Flat;
    scene.annotations.colorBars = false;
    scene.annotations.scaleBar = false;
    const render::Frame f = renderer.render(scene, coupling::particleView(g, options));
    // The body is in the view's middle (RZ: 4 m wide mirrored, 2 m high, so the middle band of
    // rows): count background pixels there, across the axis in RZ.
    int gaps = 0;
    const int w = f.image.width(), h = f.framing.plotHeight;
    for (int y = 2 * h / 5; y < 3 * h / 5; ++y)
      for (int x = w / 4; x < 3 * w / 4; ++x)
        if (f.image.at(x, y) == render::Rgba8{255, 255, 255, 255}) ++gaps;
    EXPECT_EQ(gaps, 0) << geometryName(g);
  }
}

TEST(CouplingImages, FailureStatusFollowsDamageAndPlasticStrain) {
  // One particle per state: a fluid, an intact solid, a yielded one, a cracked one, a failed one.
  ParticleSet p;
  for (int i = 0; i < 5; ++i) p.append({0.1 * i, 0.0, 0.0}, {0, 0, 0}, 1.0, 1.0, 1.0, 0.1, i == 0 ? 1 : 0);
  p.enableStrength(4);
  p.enableFracture();
  p.plasticStrain[2] = 0.02;
  p.crack[3] = std::cbrt(0.3);  // damage = crack^3
  p.crack[4] = 1.0;
  const coupling::MaterialLegend legend{{"granite", "water"}, {true, false}};
  const coupling::Categories c = coupling::failureCategories(p, legend);
  std::vector<std::string> states;
  for (std::size_t i = 0; i < 5; ++i) states.push_back(c.legend[static_cast<std::size_t>(c.of[i])].label);
  EXPECT_EQ(states, (std::vector<std::string>{"no strength", "intact", "plastic", "damaged", "failed"}));
  EXPECT_EQ(c.legend.size(), 5u);
  // Only the states present: an undamaged elastic body has one entry.
  p.plasticStrain[2] = 0.0;
  p.crack[3] = p.crack[4] = 0.0;
  p.material[0] = 0;
  EXPECT_EQ(coupling::failureCategories(p, legend).legend.size(), 1u);
  const coupling::Categories m = coupling::materialCategories(p, legend);
  EXPECT_EQ(m.legend[0].label, "granite");
  EXPECT_EQ(m.legend[1].label, "water");
}

TEST(CouplingImages, CategoryPicturesCarryTheirLegend) {
  const Scene scene = parseScene(test::tinyImpactScene(), "tiny.toml");
  const ParticleSet p = buildParticles(scene, MaterialTable::fromScene(scene));
  coupling::MaterialLegend legend;
  for (const MaterialSpec& s : scene.materials) {
    legend.names.push_back(s.name);
    legend.strength.push_back(s.strength.present);
  }
  render::RenderSettings settings;
  settings.width = settings.height = 512;
  render::Renderer renderer(settings);
  const fs::path dir = tempDir("categories");
  const coupling::Categories c = coupling::materialCategories(p, legend);
  coupling::writeCategoryImage(renderer, p, scene.geometry, 0.0, "tiny: materials", c, {}, dir / "m.png");
  const render::Image image = render::readPng(dir / "m.png");
  // Every material's colour is in the picture (its particles and its legend swatch).
  for (const render::LegendEntry& e : c.legend) {
    const render::Rgba8 want = render::toRgba8(e.color);
    bool found = false;
    for (int y = 0; y < image.height() && !found; ++y)
      for (int x = 0; x < image.width() && !found; ++x) found = image.at(x, y) == want;
    EXPECT_TRUE(found) << e.label;
  }
  fs::remove_all(dir);
}
