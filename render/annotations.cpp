#include "render/annotations.hpp"

#include <algorithm>
#include <cmath>

#include "render/font.hpp"
#include "render/labels.hpp"

namespace ejecta::render {

namespace {

// Sizes in font pixels (multiplied by the text scale).
constexpr int kPad = 6;         // around the strip's content
constexpr int kLineGap = 4;     // between lines of the left column
constexpr int kBarHeight = 10;  // the colour gradient
constexpr int kTick = 3;        // tick marks under the gradient
constexpr int kBarGap = 5;      // between colour bars

int leftLines(const Annotations& a, bool scaleBar) {
  return (a.title.empty() ? 0 : 1) + (a.time ? 1 : 0) + (scaleBar ? 1 : 0);
}

// label, 2, bar, tick, 1, tick labels
int colorBarBlock(int s) { return (kGlyphHeight + 2 + kBarHeight + kTick + 1 + kGlyphHeight) * s; }

PixelRect textBox(int x, int y, const std::string& text, int s) {
  return {x, y, x + textWidth(text, s), y + textHeight(s)};
}

}  // namespace

int stripHeight(const Annotations& a, std::size_t colorBarCount, int s) {
  const int left = leftLines(a, a.scaleBar);
  const int bars = a.colorBars ? static_cast<int>(colorBarCount) : 0;
  if (left == 0 && bars == 0) return 0;
  const int leftHeight = left > 0 ? left * (kGlyphHeight + kLineGap) * s - kLineGap * s : 0;
  const int rightHeight = bars > 0 ? bars * colorBarBlock(s) + (bars - 1) * kBarGap * s : 0;
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
  const int pad = kPad * s, line = kGlyphHeight * s;
  const int leftEnd = barCount > 0 ? imageWidth * 2 / 5 : imageWidth - pad;
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
    const int x0 = imageWidth * 9 / 20, x1 = imageWidth - pad;
    int by = top + pad;
    for (std::size_t b = 0; b < barCount; ++b) {
      const ColorScale& scale = bars[b].scale;
      ColorBarPlacement p;
      p.labelText = bars[b].label;
      const int labelWidth = textWidth(p.labelText, s);
      p.label = textBox(std::max(x0, (x0 + x1 - labelWidth) / 2), by, p.labelText, s);
      p.bar = {x0, by + line + 2 * s, x1, by + line + (2 + kBarHeight) * s};
      const int ty = p.bar.y1 + (kTick + 1) * s;
      p.minText = formatNumber(scale.min());
      p.maxText = formatNumber(scale.max());
      p.minLabel = textBox(x0, ty, p.minText, s);
      const int maxWidth = textWidth(p.maxText, s);
      p.maxLabel = textBox(x1 - maxWidth, ty, p.maxText, s);
      const double mid = scale.kind() == ScaleKind::Log ? std::sqrt(scale.min() * scale.max())
                                                        : (scale.min() + scale.max()) / 2.0;
      p.midText = formatNumber(mid);
      const int midWidth = textWidth(p.midText, s);
      const PixelRect midBox = textBox((x0 + x1 - midWidth) / 2, ty, p.midText, s);
      if (midBox.x0 > p.minLabel.x1 + 2 * s && midBox.x1 < p.maxLabel.x0 - 2 * s)
        p.midLabel = midBox;
      else
        p.midText.clear();
      out.colorBars.push_back(p);
      by += colorBarBlock(s) + kBarGap * s;
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
    // Ticks at the ends and the middle.
    const int tickBottom = r.y1 + 1 + kTick * s;
    image.fillRect(r.x0, r.y1 + 1, r.x0 + s, tickBottom, ink);
    image.fillRect(r.x1 - s, r.y1 + 1, r.x1, tickBottom, ink);
    const int xm = (r.x0 + r.x1) / 2;
    image.fillRect(xm - s / 2, r.y1 + 1, xm - s / 2 + s, tickBottom, ink);
    drawText(image, p.label.x0, p.label.y0, p.labelText, s, ink);
    drawText(image, p.minLabel.x0, p.minLabel.y0, p.minText, s, ink);
    drawText(image, p.maxLabel.x0, p.maxLabel.y0, p.maxText, s, ink);
    if (!p.midLabel.empty()) drawText(image, p.midLabel.x0, p.midLabel.y0, p.midText, s, ink);
  }
}

}  // namespace ejecta::render
