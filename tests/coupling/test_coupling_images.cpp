// The in-situ chain as a library (coupling/): a C++ user draws a run's pictures without the
// command line. These call coupling/ directly; the command-line tests (test_chain_*) go through
// the binary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <set>

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
