// The built-in bitmap font and the annotation strip, drawn on the CPU: ink lands where the
// label is and nowhere else, glyphs are the ones drawn, UTF-8 unit characters decode, the strip
// holds the colour bars with the map's end colours at its ends.
#include <gtest/gtest.h>

#include <string>

#include "render/annotations.hpp"
#include "render/font.hpp"

namespace ejecta::render {
namespace {

constexpr Rgba8 kPaper{255, 255, 255, 255};
constexpr Rgba8 kInk{0, 0, 0, 255};

int inkIn(const Image& image, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (image.contains(x, y) && image.at(x, y) != kPaper) ++n;
  return n;
}

TEST(RenderText, InkLandsInsideTheLabelsBox) {
  for (int scale : {1, 2, 3}) {
    Image image(300, 60, kPaper);
    const std::string text = "t = 1.25 ms";
    const int x = 17, y = 9;
    drawText(image, x, y, text, scale, kInk);
    const int w = textWidth(text, scale), h = textHeight(scale);
    EXPECT_EQ(w, (11 * 6 - 1) * scale);
    EXPECT_EQ(h, 7 * scale);
    const int inside = inkIn(image, x, y, x + w, y + h);
    EXPECT_GT(inside, 30 * scale * scale);
    EXPECT_EQ(inkIn(image, 0, 0, 300, 60), inside) << "ink outside the label's box";
    // The box is tight: the first and last columns and the top and bottom rows have ink.
    EXPECT_GT(inkIn(image, x, y, x + scale, y + h), 0);
    EXPECT_GT(inkIn(image, x + w - scale, y, x + w, y + h), 0);
    EXPECT_GT(inkIn(image, x, y, x + w, y + scale), 0);
    EXPECT_GT(inkIn(image, x, y + h - scale, x + w, y + h), 0);
  }
}

TEST(RenderText, GlyphsAreTheOnesDrawn) {
  // "1": a vertical stroke in the middle column with a foot across; "-": one row in the middle.
  Image one(5, 7, kPaper);
  drawText(one, 0, 0, "1", 1, kInk);
  for (int y = 0; y < 7; ++y) EXPECT_EQ(one.at(2, y), kInk) << y;
  EXPECT_EQ(inkIn(one, 1, 6, 4, 7), 3);
  EXPECT_EQ(one.at(0, 0), kPaper);
  Image dash(5, 7, kPaper);
  drawText(dash, 0, 0, "-", 1, kInk);
  EXPECT_EQ(inkIn(dash, 0, 3, 5, 4), 5);
  EXPECT_EQ(inkIn(dash, 0, 0, 5, 7), 5);
  // At scale 2 each font pixel is a 2 x 2 block.
  Image big(10, 14, kPaper);
  drawText(big, 0, 0, "-", 2, kInk);
  EXPECT_EQ(inkIn(big, 0, 6, 10, 8), 20);
  EXPECT_EQ(inkIn(big, 0, 0, 10, 14), 20);
  // Different characters, different pictures; an unknown one is a box, not nothing.
  Image a(5, 7, kPaper), b(5, 7, kPaper), unknown(5, 7, kPaper);
  drawText(a, 0, 0, "m", 1, kInk);
  drawText(b, 0, 0, "n", 1, kInk);
  drawText(unknown, 0, 0, "\xE2\x82\xAC", 1, kInk);  // the euro sign
  EXPECT_NE(a.bytes(), b.bytes());
  EXPECT_EQ(inkIn(unknown, 0, 0, 5, 7), 5 + 5 + 2 * 5);
}

TEST(RenderText, DecodesUtf8UnitCharacters) {
  EXPECT_EQ(decodeUtf8("kg/m\xC2\xB3"), (std::u32string{U'k', U'g', U'/', U'm', 0xB3}));
  EXPECT_EQ(decodeUtf8("\xC2\xB5s \xC2\xB0"
                       "C"),
            (std::u32string{0xB5, U's', U' ', 0xB0, U'C'}));
  EXPECT_EQ(decodeUtf8("a\xC2"), (std::u32string{U'a', 0xFFFD}));  // truncated sequence
  EXPECT_EQ(decodeUtf8("\xFF"), (std::u32string{0xFFFD}));
  EXPECT_EQ(textWidth("\xC2\xB5m", 1), 11);  // two glyphs, not three bytes
  // Units characters have their own glyphs (not the box).
  Image micro(5, 7, kPaper), box(5, 7, kPaper);
  drawText(micro, 0, 0, "\xC2\xB5", 1, kInk);
  drawText(box, 0, 0, "\xE2\x82\xAC", 1, kInk);
  EXPECT_NE(micro.bytes(), box.bytes());
}

TEST(RenderText, StripHoldsColourBarsTimeAndScaleBar) {
  const int width = 1024, scale = 2;
  Annotations a;
  a.title = "impact";
  a.time = 0.5;
  std::vector<ColorBarEntry> bars{
      {"temperature [K]", ColorScale(ColorMap(ColorMapName::Inferno), 300.0, 3000.0)},
      {"pressure [Pa]", ColorScale(ColorMap(ColorMapName::CoolWarm), 1e5, 1e9, ScaleKind::Log)}};
  const int height = stripHeight(a, bars.size(), scale);
  EXPECT_GT(height, 2 * 30 * scale);
  Image image(width, height + 10, kPaper);
  const StripLayout layout = layoutStrip(a, bars, width, 10, scale, 8.0);  // 8 px per metre
  drawStrip(image, layout, bars, kInk);
  ASSERT_EQ(layout.colorBars.size(), 2u);
  for (std::size_t b = 0; b < 2; ++b) {
    const PixelRect& r = layout.colorBars[b].bar;
    const int row = (r.y0 + r.y1) / 2;
    EXPECT_EQ(image.at(r.x0, row), toRgba8(bars[b].scale.map().table().front()));
    EXPECT_EQ(image.at(r.x1 - 1, row), toRgba8(bars[b].scale.map().table().back()));
    EXPECT_EQ(image.at(r.x0 - 1, row), kInk);  // the frame, outside the gradient
    EXPECT_GT(inkIn(image, layout.colorBars[b].label.x0, layout.colorBars[b].label.y0,
                    layout.colorBars[b].label.x1, layout.colorBars[b].label.y1),
              50);
    EXPECT_GE(r.y0, 10);
    EXPECT_LE(r.y1, 10 + height);
  }
  EXPECT_EQ(layout.colorBars[0].minText, "300");
  EXPECT_EQ(layout.colorBars[0].midText, "1.65e3");
  EXPECT_EQ(layout.colorBars[0].maxText, "3e3");
  EXPECT_EQ(layout.colorBars[1].midText, "1e7");  // geometric middle of a log scale
  EXPECT_EQ(layout.timeText, "t = 500 ms");       // below 1 s: milliseconds
  // The scale bar: about a fifth of 1024 px at 8 px/m is 25.6 m, rounded down to 20 m.
  EXPECT_EQ(layout.scaleMetres, 20.0);
  EXPECT_EQ(layout.scaleText, "20 m");
  EXPECT_EQ(layout.scaleBar.width(), 160);
  EXPECT_GT(
      inkIn(image, layout.scaleBar.x0, layout.scaleBar.y0, layout.scaleBar.x1, layout.scaleBar.y1),
      2 * 160);
  // The left column and the colour bars do not overlap.
  EXPECT_LT(layout.scaleLabel.x1, layout.colorBars[0].bar.x0);
  EXPECT_LT(layout.title.y1, layout.time.y0);
  // Nothing to show, no strip.
  Annotations empty;
  empty.scaleBar = false;
  EXPECT_EQ(stripHeight(empty, 0, scale), 0);
}

}  // namespace
}  // namespace ejecta::render
