#include "render/distance_axes.hpp"

#include <algorithm>
#include <cmath>

#include "render/font.hpp"
#include "render/ticks.hpp"

namespace ejecta::render {

namespace {

// std::clamp with bounds that may cross (a label wider than its room): the low bound wins.
int clampTo(int v, int lo, int hi) { return std::max(lo, std::min(v, hi)); }

// World coordinate of a pixel column (axis 0) or row (axis 1) of an orthographic framing.
struct AxisMap {
  double pixelAtZero = 0.0, pixelsPerMetre = 0.0;
  double world(double pixel) const { return (pixel - pixelAtZero) / pixelsPerMetre; }
  double pixel(double world) const { return pixelAtZero + world * pixelsPerMetre; }
};

AxisMap axisMap(const Framing& f, int axis) {
  const Vec3 zero{0.0, 0.0, 0.0};
  Vec3 one = zero;
  one[static_cast<std::size_t>(axis)] = 1.0;
  const double a = f.project(zero)[static_cast<std::size_t>(axis)];
  const double b = f.project(one)[static_cast<std::size_t>(axis)];
  return {a, b - a};
}


}  // namespace

void drawDistanceAxes(Image& image, const Framing& f, const AxisNames& names, int s, Rgba8 ink) {
  if (f.perspective || f.plotWidth <= 0 || f.plotHeight <= 0) return;
  const int tick = 5 * s, gap = 2 * s;
  for (int axis = 0; axis < 2; ++axis) {
    const AxisMap map = axisMap(f, axis);
    if (!std::isfinite(map.pixelsPerMetre) || map.pixelsPerMetre == 0.0) continue;
    const int length = axis == 0 ? f.plotWidth : f.plotHeight;
    const double a = map.world(0.0), b = map.world(length);
    const double lo = std::min(a, b), hi = std::max(a, b);
    const double step = niceStep(hi - lo, 6);
    for (double k = std::ceil(lo / step); k * step <= hi; k += 1.0) {
      const double metres = k * step;
      const int p = static_cast<int>(std::lround(map.pixel(metres)));
      if (p < 0 || p >= length) continue;
      const std::string text = roundLabel(metres, step);
      if (axis == 0) {  // along the bottom edge, labels above the marks
        image.fillRect(p - s / 2, f.plotHeight - tick, p - s / 2 + s, f.plotHeight, ink);
        const int w = textWidth(text, s);
        const int x = clampTo(p - w / 2, 0, f.plotWidth - w);
        drawText(image, x, f.plotHeight - tick - gap - textHeight(s), text, s, ink);
      } else {  // along the left edge, labels right of the marks
        image.fillRect(0, p - s / 2, tick, p - s / 2 + s, ink);
        const int y = clampTo(p - textHeight(s) / 2, 0, f.plotHeight - textHeight(s));
        // The top line holds the axis's name.
        // (Well clear of the mark, which would otherwise read as a minus sign.)
        if (y >= 2 * gap + textHeight(s)) drawText(image, tick + 3 * gap, y, text, s, ink);
      }
    }
  }
  // The axes' names at their far ends: bottom right, top left.
  const std::string h = names.horizontal + " [m]", v = names.vertical + " [m]";
  drawText(image, f.plotWidth - textWidth(h, s) - gap, f.plotHeight - tick - 2 * gap - 2 * textHeight(s), h, s, ink);
  drawText(image, tick + gap, gap, v, s, ink);
}

}  // namespace ejecta::render
