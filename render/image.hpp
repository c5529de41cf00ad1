#pragma once
// An 8-bit RGBA image in memory, rows from the top (row 0 is the top of the picture, as PNG
// stores it), and the colour type the renderer works in.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ejecta::render {

// A colour with components in [0, 1], sRGB-encoded (what a display shows), not linear light.
struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

// Rounds each component to 8 bits (clamped to [0, 1] first); alpha opaque.
Rgba8 toRgba8(const Rgb& color);

class Image {
 public:
  Image() = default;
  // Filled with `fill`. Throws std::invalid_argument for a non-positive size.
  Image(int width, int height, Rgba8 fill = {0, 0, 0, 255});

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return pixels_.empty(); }

  // Pixel (x, y): x from the left, y from the top. Unchecked; use contains() first.
  Rgba8 at(int x, int y) const {
    const std::uint8_t* p = &pixels_[offset(x, y)];
    return {p[0], p[1], p[2], p[3]};
  }
  void set(int x, int y, Rgba8 c) {
    std::uint8_t* p = &pixels_[offset(x, y)];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
    p[3] = c.a;
  }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  // Fills the rectangle [x0, x1) x [y0, y1), clipped to the image.
  void fillRect(int x0, int y0, int x1, int y1, Rgba8 c);

  // RGBA bytes, width * height * 4, top row first.
  const std::vector<std::uint8_t>& bytes() const { return pixels_; }
  std::vector<std::uint8_t>& bytes() { return pixels_; }

 private:
  std::size_t offset(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
            static_cast<std::size_t>(x)) *
           4;
  }
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace ejecta::render
