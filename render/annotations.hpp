#pragma once
// The strip under the picture: on the left the title, the simulation time and a scale bar; on
// the right one colour bar per coloured layer, with the field's name and units above it
// ("(log)" for a log scale, a shared power of ten), round ticks below it (render/ticks.hpp),
// and an arrow at each end the data run past (clipped values). Drawn on the CPU (render/font.hpp).
#include <string>
#include <vector>

#include "render/color_scale.hpp"
#include "render/image.hpp"
#include "render/scene.hpp"

namespace ejecta::render {

// Pixels [x0, x1) x [y0, y1), y from the top of the image.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

struct ColorBarEntry {
  std::string label;  // "density [kg/m^3]"
  ColorScale scale;
  // Data beyond the scale's ends (drawn in the end colour): an arrow marks each such end.
  bool clippedLow = false, clippedHigh = false;
};

struct ColorBarTick {
  int x = 0;        // the tick mark's column
  PixelRect box;    // its label; empty when it would overlap a neighbour's
  std::string text;
};

struct ColorBarPlacement {
  PixelRect bar;  // the gradient: first column = the map at 0, last column = the map at 1
  PixelRect label;
  std::string labelText;  // the entry's label, with "(log)" and the ticks' common factor
  std::vector<ColorBarTick> ticks;
  PixelRect lowArrow, highArrow;  // empty unless that end is clipped
};

struct LegendPlacement {
  PixelRect swatch, label;
  std::string text;
  Rgba8 color;
};

struct StripLayout {
  int top = 0, height = 0;  // image rows [top, top + height); height 0: no strip
  int textScale = 1;
  PixelRect title, time, scaleBar, scaleLabel;  // empty when not shown
  std::string titleText, timeText, scaleText;
  double scaleMetres = 0.0;  // the scale bar's length [m]
  std::vector<ColorBarPlacement> colorBars;
  std::vector<LegendPlacement> legend;
};

// Pixel rows the strip needs (0 when it shows nothing).
int stripHeight(const Annotations& annotations, std::size_t colorBarCount, int textScale);

// Places everything in rows [top, top + height) of an image `imageWidth` wide. The scale bar
// is a round length about a fifth of the width, `pixelsPerMetre` giving its size (<= 0: none).
StripLayout layoutStrip(const Annotations& annotations, const std::vector<ColorBarEntry>& bars,
                        int imageWidth, int top, int textScale, double pixelsPerMetre);

void drawStrip(Image& image, const StripLayout& layout, const std::vector<ColorBarEntry>& bars,
               Rgba8 ink);

}  // namespace ejecta::render
