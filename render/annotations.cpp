#include "render/annotations.hpp"

#include <algorithm>
#include <cmath>

#include "render/font.hpp"
#include "render/labels.hpp"
#include "render/ticks.hpp"

namespace ejecta::render {

namespace {

// std::clamp with bounds that may cross (a label wider than its room): the low bound wins.
int clampTo(int v, int lo, int hi) { return std::max(lo, std::min(v, hi)); }

// Sizes in font pixels (multiplied by the text scale).
constexpr int kPad = 6;         // around the strip's content
constexpr int kLineGap = 4;     // between lines of the left column
constexpr int kBarHeight = 10;  // the colour gradient
constexpr int kTick = 3;        // tick marks under the gradient
constexpr int kBarGap = 5;      // between colour bars

constexpr int kLegendColumns = 3;

int legendRows(const Annotations& a) {
  return static_cast<int>((a.legend.size() + kLegendColumns - 1) / kLegendColumns);
}

int leftLines(const Annotations& a, bool scaleBar) {
  return (a.title.empty() ? 0 : 1) + (a.time ? 1 : 0) + (scaleBar ? 1 : 0);
}

// label, 2, bar, tick, 1, tick labels
int colorBarBlock(int s) { return 2 * textHeight(s) + (2 + kBarHeight + kTick + 1) * s; }

PixelRect textBox(int x, int y, const std::string& text, int s) {
  return {x, y, x + textWidth(text, s), y + textHeight(s)};
}

}  // namespace

int stripHeight(const Annotations& a, std::size_t colorBarCount, int s) {
  const int left = leftLines(a, a.scaleBar);
  const int bars = a.colorBars ? static_cast<int>(colorBarCount) : 0;
  const int legend = legendRows(a);
  if (left == 0 && bars == 0 && legend == 0) return 0;
  const int leftHeight = left > 0 ? left * (textHeight(s) + kLineGap * s) - kLineGap * s : 0;
  int rightHeight = bars > 0 ? bars * colorBarBlock(s) + (bars - 1) * kBarGap * s : 0;
  if (legend > 0)
    rightHeight += (bars > 0 ? kBarGap * s : 0) + legend * (textHeight(s) + kLineGap * s) - kLineGap * s;
  return 2 * kPad * s + std::max(leftHeight, rightHeight);
}

StripLayout layoutStrip(const Annotations& a, const std::vector<ColorBarEntry>& bars,
                        int imageWidth, int top, int s, double pixelsPerMetre) {
  StripLayout out;
  out.top = top;
  out.textScale = s;
  const bool scaleBar = a.scaleBar && pixelsPerMetre > 0.0 && std::isfinite(pixelsPerMetre);
  const std::size_t barCount = a.colorBars ? bars.size() : 0;
  out.height = stripHeight(a, barCount, s);
  const int pad = kPad * s, line = textHeight(s);
  const int leftEnd = barCount > 0 || !a.legend.empty() ? imageWidth * 2 / 5 : imageWidth - pad;
  int y = top + pad;
  if (!a.title.empty()) {
    out.titleText = a.title;
    out.title = textBox(pad, y, a.title, s);
    y += line + kLineGap * s;
  }
  if (a.time) {
    out.timeText = formatTime(*a.time);
    out.time = textBox(pad, y, out.timeText, s);
    y += line + kLineGap * s;
  }
  if (scaleBar) {
    // A round length of about a fifth of the width, shortened until it and its label fit.
    double metres = roundLength(imageWidth / 5.0 / pixelsPerMetre);
    for (int tries = 0; tries < 8; ++tries) {
      const int length = static_cast<int>(std::lround(metres * pixelsPerMetre));
      const std::string text = formatLength(metres);
      if (pad + length + 3 * s + textWidth(text, s) <= leftEnd || tries == 7) {
        out.scaleMetres = metres;
        out.scaleText = text;
        out.scaleBar = {pad, y, pad + std::max(length, 1), y + line};
        out.scaleLabel = textBox(out.scaleBar.x1 + 3 * s, y, text, s);
        break;
      }
      metres = roundLength(metres * 0.99);
    }
  }
  if (barCount > 0) {
    int by = top + pad;
    for (std::size_t b = 0; b < barCount; ++b) {
      const ColorBarEntry& entry = bars[b];
      const TickSet ticks = colorBarTicks(entry.scale);
      ColorBarPlacement p;
      p.labelText = entry.label;
      if (entry.scale.kind() == ScaleKind::Log) p.labelText += " (log)";
      if (!ticks.factor.empty()) p.labelText += ", " + ticks.factor;
      // Arrows take room at the clipped ends, outside the gradient.
      const int arrow = kBarHeight * s;
      const int x0 = imageWidth * 9 / 20 + (entry.clippedLow ? arrow + s : 0);
      const int x1 = imageWidth - pad - (entry.clippedHigh ? arrow + s : 0);
      const int labelWidth = textWidth(p.labelText, s);
      p.label = textBox(std::max(x0, (x0 + x1 - labelWidth) / 2), by, p.labelText, s);
      p.bar = {x0, by + line + 2 * s, x1, by + line + (2 + kBarHeight) * s};
      if (entry.clippedLow) p.lowArrow = {x0 - s - arrow, p.bar.y0, x0 - s, p.bar.y1};
      if (entry.clippedHigh) p.highArrow = {x1 + s, p.bar.y0, x1 + s + arrow, p.bar.y1};
      const int ty = p.bar.y1 + (kTick + 1) * s;
      int lastRight = -1 << 30;
      for (const Tick& t : ticks.ticks) {
        ColorBarTick placed;
        placed.x = x0 + static_cast<int>(std::lround(t.position * (x1 - x0 - 1)));
        placed.text = t.text;
        const int w = textWidth(t.text, s);
        const int left = clampTo(placed.x - w / 2, x0, x1 - w);
        if (left > lastRight + 2 * s) {
          placed.box = textBox(left, ty, t.text, s);
          lastRight = placed.box.x1;
        }
        p.ticks.push_back(placed);
      }
      out.colorBars.push_back(p);
      by += colorBarBlock(s) + kBarGap * s;
    }
  }
  if (!a.legend.empty()) {
    // Below the colour bars: a grid of swatch-and-name cells, three to a row.
    int ly = top + pad;
    if (barCount > 0) ly += static_cast<int>(barCount) * (colorBarBlock(s) + kBarGap * s);
    const int x0 = imageWidth * 9 / 20, x1 = imageWidth - pad;
    const int cell = (x1 - x0) / kLegendColumns, swatch = textHeight(s);
    for (std::size_t k = 0; k < a.legend.size(); ++k) {
      const int row = static_cast<int>(k) / kLegendColumns, column = static_cast<int>(k) % kLegendColumns;
      const int cx = x0 + column * cell, cy = ly + row * (textHeight(s) + kLineGap * s);
      LegendPlacement e;
      e.swatch = {cx, cy, cx + swatch, cy + swatch};
      e.text = a.legend[k].label;
      e.label = textBox(cx + swatch + 3 * s, cy, e.text, s);
      e.color = toRgba8(a.legend[k].color);
      out.legend.push_back(e);
    }
  }
  return out;
}

void drawStrip(Image& image, const StripLayout& layout, const std::vector<ColorBarEntry>& bars,
               Rgba8 ink) {
  const int s = layout.textScale;
  if (!layout.title.empty())
    drawText(image, layout.title.x0, layout.title.y0, layout.titleText, s, ink);
  if (!layout.time.empty())
    drawText(image, layout.time.x0, layout.time.y0, layout.timeText, s, ink);
  if (!layout.scaleBar.empty()) {
    const PixelRect& r = layout.scaleBar;
    const int mid = (r.y0 + r.y1) / 2;
    image.fillRect(r.x0, mid - s, r.x1, mid + s, ink);  // the bar
    image.fillRect(r.x0, r.y0, r.x0 + s, r.y1, ink);    // end caps
    image.fillRect(r.x1 - s, r.y0, r.x1, r.y1, ink);
    drawText(image, layout.scaleLabel.x0, layout.scaleLabel.y0, layout.scaleText, s, ink);
  }
  for (std::size_t b = 0; b < layout.colorBars.size(); ++b) {
    const ColorBarPlacement& p = layout.colorBars[b];
    const ColorScale& scale = bars[b].scale;
    const PixelRect& r = p.bar;
    // A one-pixel frame just outside the gradient, so its end columns keep the map's ends.
    image.fillRect(r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y0, ink);
    image.fillRect(r.x0 - 1, r.y1, r.x1 + 1, r.y1 + 1, ink);
    image.fillRect(r.x0 - 1, r.y0, r.x0, r.y1, ink);
    image.fillRect(r.x1, r.y0, r.x1 + 1, r.y1, ink);
    const int columns = r.width();
    for (int x = r.x0; x < r.x1; ++x) {
      const double t = columns > 1 ? static_cast<double>(x - r.x0) / (columns - 1) : 0.0;
      image.fillRect(x, r.y0, x + 1, r.y1, toRgba8(scale.map().at(t)));
    }
    const int tickBottom = r.y1 + 1 + kTick * s;
    for (const ColorBarTick& t : p.ticks) {
      const int left = clampTo(t.x - s / 2, r.x0, r.x1 - s);
      image.fillRect(left, r.y1 + 1, left + s, tickBottom, ink);
      if (!t.box.empty()) drawText(image, t.box.x0, t.box.y0, t.text, s, ink);
    }
    // A clipped end: a triangle in the end colour pointing away from the bar, outlined.
    const auto drawArrow = [&](const PixelRect& a, bool pointsLeft, Rgba8 fill) {
      if (a.empty()) return;
      const int h = a.height();
      for (int col = 0; col < a.width(); ++col) {
        const double reach = pointsLeft ? static_cast<double>(col + 1) / a.width()
                                        : static_cast<double>(a.width() - col) / a.width();
        const int half = static_cast<int>(std::lround(reach * h / 2.0));
        const int mid = a.y0 + h / 2;
        image.fillRect(a.x0 + col, mid - half, a.x0 + col + 1, mid + half, fill);
        image.fillRect(a.x0 + col, mid - half - 1, a.x0 + col + 1, mid - half, ink);
        image.fillRect(a.x0 + col, mid + half, a.x0 + col + 1, mid + half + 1, ink);
      }
    };
    drawArrow(p.lowArrow, true, toRgba8(scale.map().at(0.0)));
    drawArrow(p.highArrow, false, toRgba8(scale.map().at(1.0)));
    drawText(image, p.label.x0, p.label.y0, p.labelText, s, ink);
  }
  for (const LegendPlacement& e : layout.legend) {
    const PixelRect& r = e.swatch;
    image.fillRect(r.x0, r.y0, r.x1, r.y1, ink);  // a frame, then the colour inside it
    image.fillRect(r.x0 + 1, r.y0 + 1, r.x1 - 1, r.y1 - 1, e.color);
    drawText(image, e.label.x0, e.label.y0, e.text, s, ink);
  }
}

}  // namespace ejecta::render
