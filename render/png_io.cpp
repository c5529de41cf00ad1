#include "render/png_io.hpp"

#include <png.h>

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "core/atomic_file.hpp"

// libpng's "simplified API" (png_image_*) reports errors in the png_image structure instead of
// longjmp, so no C++ object is ever skipped over by a jump.
namespace ejecta::render {

namespace {

// Frees libpng's read state on every path out.
struct PngImage {
  png_image image;
  PngImage() {
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
  }
  ~PngImage() { png_image_free(&image); }
  PngImage(const PngImage&) = delete;
  PngImage& operator=(const PngImage&) = delete;
};

}  // namespace

std::string encodePng(const Image& image, const PngOptions& options) {
  if (image.empty()) throw std::invalid_argument("encodePng: the image is empty");
  PngImage png;
  png.image.width = static_cast<png_uint_32>(image.width());
  png.image.height = static_cast<png_uint_32>(image.height());
  png.image.format = PNG_FORMAT_RGBA;
  if (options.fast) png.image.flags |= PNG_IMAGE_FLAG_FAST;
  std::vector<std::uint8_t> rgb;
  const void* pixels = image.bytes().data();
  if (options.channels == PngChannels::Rgb) {
    // Drop alpha here: libpng would composite it on a background, changing the colours.
    png.image.format = PNG_FORMAT_RGB;
    const std::vector<std::uint8_t>& src = image.bytes();
    rgb.resize(src.size() / 4 * 3);
    for (std::size_t i = 0, j = 0; i < src.size(); i += 4, j += 3) {
      rgb[j] = src[i];
      rgb[j + 1] = src[i + 1];
      rgb[j + 2] = src[i + 2];
    }
    pixels = rgb.data();
  }
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&png.image, nullptr, &size, 0, pixels, 0, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.image.message);
  std::string bytes(size, '\0');
  if (!png_image_write_to_memory(&png.image, bytes.data(), &size, 0, pixels, 0, nullptr))
    throw std::runtime_error(std::string("PNG encoding failed: ") + png.image.message);
  bytes.resize(size);
  return bytes;
}

void writePng(const std::filesystem::path& path, const Image& image, const PngOptions& options) {
  std::string bytes;
  try {
    bytes = encodePng(image, options);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write '" + path.string() + "': " + e.what());
  }
  writeFileAtomically(path, bytes);
}

Image readPng(const std::filesystem::path& path) {
  PngImage png;
  if (!png_image_begin_read_from_file(&png.image, path.c_str()))
    throw std::runtime_error("cannot read PNG '" + path.string() + "': " + png.image.message);
  png.image.format = PNG_FORMAT_RGBA;
  Image out(static_cast<int>(png.image.width), static_cast<int>(png.image.height));
  if (!png_image_finish_read(&png.image, nullptr, out.bytes().data(), 0, nullptr))
    throw std::runtime_error("cannot read PNG '" + path.string() + "': " + png.image.message);
  return out;
}

}  // namespace ejecta::render
