// A 3D picture through a camera the user places ([images.camera] in a scene, --camera/--target/
// --up on `ejecta render`): a block of particles on the +x side of the origin must appear on the
// left of a picture taken from +y and on the right of one taken from -y (z up), and a cut moved
// with cut_at / --cut-at must remove what lies beyond it. Bad camera keys are refused with the
// scene file and key named.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "render/png_io.hpp"
#include "sim/setup/scene.hpp"
#include "support/command_line.hpp"
#include "support/temp_dir_test.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::runCommand;
using ejecta::test::writeTextFile;

// A granite block x in [0.3, 1.3] m, y and z in [-0.5, 0.5] m at rest: a few steps, one snapshot.
std::string blockScene(const std::string& images = "") {
  return R"(
[scene]
name = "block"
dimension = "3d"
[time]
t_end = "2 us"
[output]
snapshot_interval = "2 us"
)" + images + R"(
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
[[bodies]]
name = "block"
material = "granite"
shape = "box"
min = [0.3, -0.5, -0.5]
max = [1.3, 0.5, 0.5]
spacing = 0.1
density = 2680.0
pressure = 0.0
)";
}

// Coloured (not white) pixels in the left and right halves of the picture above its strip.
struct Halves {
  long left = 0, right = 0;
};
Halves colouredHalves(const fs::path& png) {
  const ejecta::render::Image image = ejecta::render::readPng(png);
  Halves h;
  const int rows = image.height() * 3 / 4;  // the strip is below
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < image.width(); ++x) {
      const auto c = image.at(x, y);
      if (c.r == 255 && c.g == 255 && c.b == 255) continue;
      (x < image.width() / 2 ? h.left : h.right) += 1;
    }
  return h;
}

class Camera : public ejecta::test::TempDirTest {
 protected:
  // Runs the block with this [images] table; returns the run directory.
  fs::path runBlock(const std::string& images) {
    writeTextFile(dir_ / "block.toml", blockScene(images));
    std::string out;
    EXPECT_EQ(runCommand(kEjecta + " run " + (dir_ / "block.toml").string() + " --out " +
                             (dir_ / "run").string() + " --threads 1 --no-charts",
                         out),
              0)
        << out;
    return dir_ / "run";
  }
};

TEST_F(Camera, RenderCommandPlacesTheCameraWhereAsked) {
  const fs::path run = runBlock("");
  std::string out;
  // From +y looking at the origin with z up, +x is on the left; from -y it is on the right.
  const std::string common = " --cut none --size 256 --target 0,0,0 --up 0,0,1 --fov 40";
  ASSERT_EQ(runCommand(kEjecta + " render " + run.string() + " --camera 0,6,0" + common + " --out " +
                           (dir_ / "plus_y.png").string(), out), 0) << out;
  ASSERT_EQ(runCommand(kEjecta + " render " + run.string() + " --camera \"0,-6 m,0\"" + common +
                           " --out " + (dir_ / "minus_y.png").string(), out), 0) << out;
  const Halves plus = colouredHalves(dir_ / "plus_y.png");
  const Halves minus = colouredHalves(dir_ / "minus_y.png");
  // The block spans x = 0.3 to 1.3 m: wholly on one side of the line of sight. Sprites are
  // sized by h, so a few pixels of the nearest column may reach across the middle: 5% allowed.
  EXPECT_GT(plus.left, 500);
  EXPECT_LT(plus.right, plus.left / 20) << "from +y the block must be on the left";
  EXPECT_GT(minus.right, 500);
  EXPECT_LT(minus.left, minus.right / 20) << "from -y the block must be on the right";
  // The same picture but cut at x = 0.2 m (keep x <= 0.2): the whole block is gone.
  ASSERT_EQ(runCommand(kEjecta + " render " + run.string() + " --camera 0,-6,0 --target 0,0,0 --cut x --cut-at 0.2 --size 256 --out " +
                           (dir_ / "cut.png").string(), out), 0) << out;
  const Halves cut = colouredHalves(dir_ / "cut.png");
  EXPECT_EQ(cut.left + cut.right, 0) << "the cut at x = 0.2 m must remove the block";
}

TEST_F(Camera, RenderCommandRefusesAHalfGivenCamera) {
  const fs::path run = runBlock("");
  std::string out;
  EXPECT_NE(runCommand(kEjecta + " render " + run.string() + " --camera 0,6,0", out), 0);
  EXPECT_NE(out.find("--target"), std::string::npos) << out;
  EXPECT_NE(runCommand(kEjecta + " render " + run.string() + " --camera 0,6,0 --target 0,0,0 --up 0,1,0", out), 0);
  EXPECT_NE(out.find("up"), std::string::npos) << out;
  EXPECT_NE(runCommand(kEjecta + " render " + run.string() + " --camera 0,6 --target 0,0,0", out), 0);
  EXPECT_NE(out.find("three components"), std::string::npos) << out;
}

TEST_F(Camera, RenderCommandFramesAPlanePicture) {
  // The block seen as a plane section (x, y): framed on x = 0.8 m it fills the middle; framed
  // 3 m to its side it is out of the picture. --center and --width come together, and not for
  // a 3D picture.
  const fs::path run = runBlock("");
  std::string out;
  const std::string plane = " --view plane --size 256 --width \"2 m\" --out ";
  ASSERT_EQ(runCommand(kEjecta + " render " + run.string() + " --center 0.8,0" + plane + (dir_ / "on.png").string(), out), 0) << out;
  ASSERT_EQ(runCommand(kEjecta + " render " + run.string() + " --center \"3.8 m,0\"" + plane + (dir_ / "off.png").string(), out), 0) << out;
  const Halves on = colouredHalves(dir_ / "on.png");
  const Halves off = colouredHalves(dir_ / "off.png");
  EXPECT_GT(on.left, 500);
  EXPECT_GT(on.right, 500);
  EXPECT_EQ(off.left + off.right, 0) << "framed 3 m aside, the block must be out of the picture";
  EXPECT_NE(runCommand(kEjecta + " render " + run.string() + " --view plane --center 0.8,0", out), 0);
  EXPECT_NE(out.find("give both"), std::string::npos) << out;
  EXPECT_NE(runCommand(kEjecta + " render " + run.string() + " --center 0.8,0 --width 2", out), 0);
  EXPECT_NE(out.find("3D"), std::string::npos) << out;
}

TEST_F(Camera, SceneCameraDrawsTheRunsFrames) {
  const fs::path run = runBlock(R"([images]
fields = ["density"]
size = 256
cut = "none"
[images.camera]
position = ["0 m", "6 m", "0 m"]
target = [0.0, 0.0, 0.0]
fov_degrees = 40
)");
  const fs::path frame = run / "images" / "density_0001.png";
  ASSERT_TRUE(fs::exists(frame)) << frame;
  const Halves h = colouredHalves(frame);
  EXPECT_GT(h.left, 500);
  EXPECT_LT(h.right, h.left / 20) << "from +y (z up, the default) the block must be on the left";
}

TEST(CameraKeys, AreCheckedWithTheirNames) {
  auto error = [](const std::string& images, const std::string& dimension = "3d") -> std::string {
    std::string text = blockScene(images);
    if (dimension != "3d") {
      text.replace(text.find("\"3d\""), 4, "\"" + dimension + "\"");
      text.replace(text.find("min = [0.3, -0.5, -0.5]"), 23, "min = [0.3, -0.5]");
      text.replace(text.find("max = [1.3, 0.5, 0.5]"), 21, "max = [1.3, 0.5]");
    }
    try {
      ejecta::parseScene(text, "block.toml");
    } catch (const ejecta::SceneError& e) {
      return e.what();
    }
    return "";
  };
  const std::string camera = "[images]\n[images.camera]\nposition = [0, 6, 0]\ntarget = [0, 0, 0]\n";
  EXPECT_EQ(error(camera), "");
  const std::string rz = error(camera, "rz");
  EXPECT_NE(rz.find("block.toml"), std::string::npos) << rz;
  EXPECT_NE(rz.find("images.camera"), std::string::npos) << rz;
  const std::string along = error(camera + "up = [0, 1, 0]\n");
  EXPECT_NE(along.find("images.camera.up"), std::string::npos) << along;
  const std::string fov = error(camera + "fov_degrees = 180\n");
  EXPECT_NE(fov.find("images.camera.fov_degrees"), std::string::npos) << fov;
  const std::string missing = error("[images]\n[images.camera]\nposition = [0, 6, 0]\n");
  EXPECT_NE(missing.find("images.camera.target"), std::string::npos) << missing;
  const std::string same = error("[images]\n[images.camera]\nposition = [1, 1, 1]\ntarget = [1, 1, 1]\n");
  EXPECT_NE(same.find("images.camera.target"), std::string::npos) << same;
  const std::string cutAt = error("[images]\ncut = \"none\"\ncut_at = \"1 m\"\n");
  EXPECT_NE(cutAt.find("images.cut_at"), std::string::npos) << cutAt;
  EXPECT_EQ(error("[images]\ncut = \"x\"\ncut_at = \"0.8 m\"\n"), "");
}

}  // namespace
