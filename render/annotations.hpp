#pragma once
// The strip under the picture: on the left the title, the simulation time and a scale bar; on
// the right one colour bar per coloured layer, with the field's name and units above it and
// its minimum, middle and maximum values below. Drawn on the CPU with the built-in font.
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
};

struct ColorBarPlacement {
  PixelRect bar;  // the gradient: first column = the map at 0, last column = the map at 1
  PixelRect label, minLabel, midLabel, maxLabel;  // midLabel empty when it would not fit
  std::string labelText, minText, midText, maxText;
};

struct StripLayout {
  int top = 0, height = 0;  // image rows [top, top + height); height 0: no strip
  int textScale = 1;
  PixelRect title, time, scaleBar, scaleLabel;  // empty when not shown
  std::string titleText, timeText, scaleText;
  double scaleMetres = 0.0;  // the scale bar's length [m]
  std::vector<ColorBarPlacement> colorBars;
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
