// PNG files: the round trip through libpng keeps size and pixels (RGB and RGBA), a write to a
// directory that cannot be written throws naming the path and leaves no temporary file, an
// existing file is replaced whole; frame names of a run.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "core/atomic_file.hpp"
#include "render/frame_names.hpp"
#include "render/png_io.hpp"

namespace ejecta::render {
namespace {

namespace fs = std::filesystem;

// A fresh directory under the build tree's temporary area, removed afterwards.
class TempDir {
 public:
  TempDir() {
    std::random_device entropy;
    path_ = fs::temp_directory_path() /
            ("ejecta-render-png-" + std::to_string(::getpid()) + "-" + std::to_string(entropy()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ignored);
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Every pixel different, alpha varying: a test image no codec can get right by accident.
Image pattern(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      image.set(x, y,
                {static_cast<std::uint8_t>(x * 7 + y), static_cast<std::uint8_t>(y * 13),
                 static_cast<std::uint8_t>((x ^ y) * 3), static_cast<std::uint8_t>(255 - x)});
  return image;
}

int filesIn(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(RenderPng, RoundTripKeepsSizeAndPixels) {
  TempDir dir;
  const Image image = pattern(37, 23);  // odd sizes: no row padding assumptions
  const fs::path rgba = dir.path() / "rgba.png";
  writePng(rgba, image, {PngChannels::Rgba, false});
  const Image back = readPng(rgba);
  ASSERT_EQ(back.width(), 37);
  ASSERT_EQ(back.height(), 23);
  EXPECT_EQ(back.bytes(), image.bytes());
  // RGB drops alpha and keeps the colours (read back as opaque); fast mode decodes the same.
  const fs::path rgb = dir.path() / "rgb.png";
  writePng(rgb, image, {PngChannels::Rgb, true});
  const Image opaque = readPng(rgb);
  ASSERT_EQ(opaque.width(), 37);
  for (int y = 0; y < 23; ++y)
    for (int x = 0; x < 37; ++x) {
      Rgba8 want = image.at(x, y);
      want.a = 255;
      ASSERT_EQ(opaque.at(x, y), want) << x << ", " << y;
    }
  // The file starts with the PNG signature and holds no temporary siblings.
  std::ifstream in(rgb, std::ios::binary);
  char signature[8];
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_EQ(filesIn(dir.path()), 2);
}

TEST(RenderPng, FailedWriteThrowsNamingThePathAndLeavesNothing) {
  // A path below a regular file: unwritable for every user, root included.
  TempDir dir;
  const fs::path blocker = dir.path() / "not_a_directory";
  std::ofstream(blocker) << "x";
  const fs::path target = blocker / "frame.png";
  try {
    writePng(target, pattern(4, 4));
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(target.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(filesIn(dir.path()), 1);
  // A read-only directory (for users other than root, who may write anyway).
  const fs::path locked = dir.path() / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  if (::geteuid() != 0) {
    EXPECT_THROW(writePng(locked / "frame.png", pattern(4, 4)), std::runtime_error);
    EXPECT_EQ(filesIn(locked), 0);
  }
  // A missing directory.
  try {
    writePng(dir.path() / "missing" / "frame.png", pattern(4, 4));
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/frame.png"), std::string::npos) << e.what();
  }
}

TEST(RenderPng, ReplacesAnExistingFileWhole) {
  TempDir dir;
  const fs::path target = dir.path() / "frame.png";
  writePng(target, pattern(64, 64));
  writePng(target, pattern(8, 5));
  const Image back = readPng(target);
  EXPECT_EQ(back.width(), 8);
  EXPECT_EQ(back.height(), 5);
  EXPECT_EQ(filesIn(dir.path()), 1);
  // Not a PNG: a clear error naming the file.
  writeFileAtomically(dir.path() / "fake.png", "hello");
  try {
    readPng(dir.path() / "fake.png");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("fake.png"), std::string::npos) << e.what();
  }
}

TEST(RenderPng, FrameNames) {
  EXPECT_EQ(framePath("run", "density", 7), fs::path("run/images/density_0007.png"));
  EXPECT_EQ(framePath("/tmp/r", "rz-temperature", 12345),
            fs::path("/tmp/r/images/rz-temperature_12345.png"));
  EXPECT_THROW(framePath("run", "", 0), std::invalid_argument);
  EXPECT_THROW(framePath("run", "a/b", 0), std::invalid_argument);
  EXPECT_THROW(framePath("run", "..", 0), std::invalid_argument);
  EXPECT_THROW(framePath("run", "view", -1), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::render
