#include "render/image.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ejecta::render {

namespace {
std::uint8_t toByte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}
}  // namespace

Rgba8 toRgba8(const Rgb& color) { return {toByte(color.r), toByte(color.g), toByte(color.b), 255}; }

Image::Image(int width, int height, Rgba8 fill) : width_(width), height_(height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("image size must be positive, got " + std::to_string(width) +
                                " x " + std::to_string(height));
  pixels_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  fillRect(0, 0, width, height, fill);
}

void Image::fillRect(int x0, int y0, int x1, int y1, Rgba8 c) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, width_);
  y1 = std::min(y1, height_);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) set(x, y, c);
}

}  // namespace ejecta::render
