#pragma once
// PNG files of Images (libpng), 8 bits per channel, RGB or RGBA.
#include <cstdint>
#include <filesystem>
#include <string>

#include "render/image.hpp"

namespace ejecta::render {

enum class PngChannels { Rgb, Rgba };

struct PngOptions {
  PngChannels channels = PngChannels::Rgb;
  // libpng's fast mode: less compression (bigger file), a few times quicker to encode.
  bool fast = false;
};

// The PNG file's bytes.
std::string encodePng(const Image& image, const PngOptions& options = {});

// Writes `image` to `path` atomically (a temporary file in the same directory, then rename).
// Throws std::runtime_error naming the path on failure; no temporary file is left behind.
void writePng(const std::filesystem::path& path, const Image& image,
              const PngOptions& options = {});

// Reads any PNG libpng can read, converted to 8-bit RGBA. Throws std::runtime_error naming the
// path and libpng's reason.
Image readPng(const std::filesystem::path& path);

}  // namespace ejecta::render
