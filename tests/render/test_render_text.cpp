// Text and the annotation strip, drawn on the CPU: the bitmap fallback's exact glyphs; the outline
// font's ink inside its box, its descenders (no more "dama9e") and smooth edges, the unit
// characters' own glyphs; colour-bar ticks at round values, shared factors, log decades, clipping
// arrows; the strip's colour bars with the map's end colours at their ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "render/annotations.hpp"
#include "render/font.hpp"
#include "render/ticks.hpp"

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

// The bitmap font (the fallback, render/bitmap_font.cpp): exact pixels.
TEST(RenderBitmapText, InkLandsInsideTheLabelsBox) {
  for (int scale : {1, 2, 3}) {
    Image image(300, 60, kPaper);
    const std::string text = "t = 1.25 ms";
    const int x = 17, y = 9;
    bitmap::drawText(image, x, y, text, scale, kInk);
    const int w = bitmap::textWidth(text, scale), h = bitmap::textHeight(scale);
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

TEST(RenderBitmapText, GlyphsAreTheOnesDrawn) {
  // "1": a vertical stroke in the middle column with a foot across; "-": one row in the middle.
  Image one(5, 7, kPaper);
  bitmap::drawText(one, 0, 0, "1", 1, kInk);
  for (int y = 0; y < 7; ++y) EXPECT_EQ(one.at(2, y), kInk) << y;
  EXPECT_EQ(inkIn(one, 1, 6, 4, 7), 3);
  EXPECT_EQ(one.at(0, 0), kPaper);
  Image dash(5, 7, kPaper);
  bitmap::drawText(dash, 0, 0, "-", 1, kInk);
  EXPECT_EQ(inkIn(dash, 0, 3, 5, 4), 5);
  EXPECT_EQ(inkIn(dash, 0, 0, 5, 7), 5);
  // At scale 2 each font pixel is a 2 x 2 block.
  Image big(10, 14, kPaper);
  bitmap::drawText(big, 0, 0, "-", 2, kInk);
  EXPECT_EQ(inkIn(big, 0, 6, 10, 8), 20);
  EXPECT_EQ(inkIn(big, 0, 0, 10, 14), 20);
  // Different characters, different pictures; an unknown one is a box, not nothing.
  Image a(5, 7, kPaper), b(5, 7, kPaper), unknown(5, 7, kPaper);
  bitmap::drawText(a, 0, 0, "m", 1, kInk);
  bitmap::drawText(b, 0, 0, "n", 1, kInk);
  bitmap::drawText(unknown, 0, 0, "\xE2\x82\xAC", 1, kInk);  // the euro sign
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
  EXPECT_EQ(bitmap::textWidth("\xC2\xB5m", 1), 11);  // two glyphs, not three bytes
  Image micro(5, 7, kPaper), box(5, 7, kPaper);
  bitmap::drawText(micro, 0, 0, "\xC2\xB5", 1, kInk);
  bitmap::drawText(box, 0, 0, "\xE2\x82\xAC", 1, kInk);
  EXPECT_NE(micro.bytes(), box.bytes());
}

// The outline font (DejaVu Sans through FreeType), where the machine has it.
class RenderOutlineText : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!outlineFontAvailable()) {
      // A build with FreeType on a machine with the font must use it (install-deps.sh installs both).
      ASSERT_FALSE(std::filesystem::exists("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf") &&
                   std::filesystem::exists("/usr/include/freetype2/ft2build.h"))
          << "FreeType and DejaVu Sans are installed but text falls back to the bitmap font";
      GTEST_SKIP() << "no outline font: the bitmap font draws text";
    }
  }
  // The lowest and highest rows with ink.
  static std::pair<int, int> inkRows(const Image& image) {
    int top = image.height(), bottom = -1;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x)
        if (image.at(x, y) != kPaper) {
          top = std::min(top, y);
          bottom = std::max(bottom, y);
        }
    return {top, bottom};
  }
};

TEST_F(RenderOutlineText, InkLandsInsideTheLabelsBox) {
  for (int scale : {1, 2, 3}) {
    Image image(400, 120, kPaper);
    const std::string text = "damage, kg/m^3, t = 1.25 ms";
    const int x = 17, y = 9;
    drawText(image, x, y, text, scale, kInk);
    const int w = textWidth(text, scale), h = textHeight(scale);
    EXPECT_GT(w, 100 * scale);
    EXPECT_GE(h, 12 * scale);  // an 11-pixel em per scale, plus ascender and descender room
    const int inside = inkIn(image, x, y, x + w, y + h);
    EXPECT_GT(inside, 60 * scale * scale);
    EXPECT_EQ(inkIn(image, 0, 0, 400, 120), inside) << "ink outside the label's box";
    EXPECT_GT(textWidth(text + "x", scale), w);
  }
}

TEST_F(RenderOutlineText, DescendersDropBelowTheBaselineAndEdgesAreSmooth) {
  // "dama9e" was the bitmap font's "damage": g and p have descenders, a and m do not.
  Image a(40, 40, kPaper), g(40, 40, kPaper), p(40, 40, kPaper);
  drawText(a, 2, 2, "a", 2, kInk);
  drawText(g, 2, 2, "g", 2, kInk);
  drawText(p, 2, 2, "p", 2, kInk);
  EXPECT_GE(inkRows(g).second, inkRows(a).second + 4);
  EXPECT_GE(inkRows(p).second, inkRows(a).second + 4);
  EXPECT_EQ(inkRows(g).second, inkRows(p).second);
  // Anti-aliased: edge pixels between paper and ink.
  int grey = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x)
      if (const Rgba8 c = g.at(x, y); c.r > 20 && c.r < 235) ++grey;
  EXPECT_GT(grey, 5);
}

TEST_F(RenderOutlineText, UnitCharactersHaveTheirOwnGlyphs) {
  // The font's box for a code point it lacks (a private-use one) against the unit characters.
  Image missing(30, 30, kPaper);
  drawText(missing, 2, 2, "\xEE\x80\x80", 2, kInk);  // U+E000
  for (const char* unit : {"\xC2\xB5", "\xC2\xB3", "\xC2\xB0", "\xC3\x97", "m", "n"}) {
    Image image(30, 30, kPaper);
    drawText(image, 2, 2, unit, 2, kInk);
    EXPECT_GT(inkIn(image, 0, 0, 30, 30), 5) << unit;
    EXPECT_NE(image.bytes(), missing.bytes()) << unit;
  }
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
  // Round ticks: 300 .. 3000 K at steps of 500; a log scale at its decades, marked "(log)".
  const auto texts = [&](std::size_t b) {
    std::vector<std::string> out;
    for (const ColorBarTick& t : layout.colorBars[b].ticks) out.push_back(t.text);
    return out;
  };
  EXPECT_EQ(texts(0), (std::vector<std::string>{"500", "1000", "1500", "2000", "2500", "3000"}));
  EXPECT_EQ(texts(1), (std::vector<std::string>{"1e5", "1e6", "1e7", "1e8", "1e9"}));
  EXPECT_EQ(layout.colorBars[0].labelText, "temperature [K]");
  EXPECT_EQ(layout.colorBars[1].labelText, "pressure [Pa] (log)");
  for (const ColorBarTick& t : layout.colorBars[1].ticks) EXPECT_FALSE(t.box.empty()) << t.text;
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

TEST(RenderTicks, RoundStepsSharedFactorsAndDecades) {
  EXPECT_DOUBLE_EQ(niceStep(10.0, 5), 2.0);
  EXPECT_DOUBLE_EQ(niceStep(2700.0, 5), 500.0);
  EXPECT_DOUBLE_EQ(niceStep(0.9, 5), 0.2);
  EXPECT_DOUBLE_EQ(niceStep(1.21e10, 5), 2e9);
  // Pascals of a shock: one factor written with the label, short numbers at the ticks.
  const TickSet gpa = colorBarTicks(ColorScale(ColorMap(ColorMapName::Viridis), 1.57, 1.21e10));
  EXPECT_EQ(gpa.factor, "\xC3\x97" "1e9");
  std::vector<std::string> texts;
  for (const Tick& t : gpa.ticks) texts.push_back(t.text);
  // (0 is within a millionth of a step of the 1.57 Pa minimum: it marks the bar's start.)
  EXPECT_EQ(texts, (std::vector<std::string>{"0", "2", "4", "6", "8", "10", "12"}));
  for (const Tick& t : gpa.ticks) {
    EXPECT_GE(t.position, 0.0);
    EXPECT_LE(t.position, 1.0);
  }
  // A small range in the middle of large numbers: enough digits to tell the ticks apart.
  const TickSet narrow = colorBarTicks(ColorScale(ColorMap(ColorMapName::Viridis), 2680.0, 2690.0));
  EXPECT_TRUE(narrow.factor.empty());
  EXPECT_EQ(narrow.ticks.front().text, "2680");
  EXPECT_EQ(narrow.ticks[1].text, "2682");
  // Under two decades, a log scale marks 1, 2 and 5 of each.
  const TickSet log = colorBarTicks(ColorScale(ColorMap(ColorMapName::Viridis), 300.0, 8000.0, ScaleKind::Log));
  texts.clear();
  for (const Tick& t : log.ticks) texts.push_back(t.text);
  EXPECT_EQ(texts, (std::vector<std::string>{"500", "1000", "2000", "5000"}));
}

TEST(RenderTicks, DegenerateRangesEndQuicklyWithTheirEndsMarked) {
  // A range a few rounding steps wide (a nearly uniform field): the two ends, told apart.
  const double lo = 2700.0, hi = std::nextafter(std::nextafter(2700.0, 3000.0), 3000.0);
  const TickSet few = colorBarTicks(ColorScale(ColorMap(ColorMapName::Viridis), lo, hi));
  ASSERT_EQ(few.ticks.size(), 2u);
  EXPECT_NE(few.ticks[0].text, few.ticks[1].text);
  // Negative ranges keep the tick at their upper end.
  const TickSet negative = colorBarTicks(ColorScale(ColorMap(ColorMapName::Viridis), -5e6, -1e6));
  EXPECT_DOUBLE_EQ(negative.ticks.back().value, -1e6);
  EXPECT_EQ(negative.factor, "\xC3\x97" "1e6");
  // Sixty decades: about six labels, not sixty.
  const TickSet wide = colorBarTicks(ColorScale(ColorMap(ColorMapName::Viridis), 1e-30, 1e30, ScaleKind::Log));
  EXPECT_LE(wide.ticks.size(), 7u);
  EXPECT_GE(wide.ticks.size(), 5u);
}

TEST(RenderText, ClippedEndsGetArrows) {
  Annotations a;
  a.scaleBar = false;
  std::vector<ColorBarEntry> bars{
      {"temperature [K]", ColorScale(ColorMap(ColorMapName::Inferno), 300.0, 800.0), false, true}};
  const int scale = 2, width = 800;
  const int height = stripHeight(a, 1, scale);
  Image image(width, height, kPaper);
  const StripLayout layout = layoutStrip(a, bars, width, 0, scale, 0.0);
  drawStrip(image, layout, bars, kInk);
  const ColorBarPlacement& p = layout.colorBars[0];
  EXPECT_TRUE(p.lowArrow.empty());
  ASSERT_FALSE(p.highArrow.empty());
  EXPECT_GT(p.highArrow.x0, p.bar.x1);  // beyond the gradient's end, inside the image
  EXPECT_LE(p.highArrow.x1, width);
  // Filled with the map's last colour (what the clipped particles are drawn in).
  const int row = (p.highArrow.y0 + p.highArrow.y1) / 2;
  EXPECT_EQ(image.at(p.highArrow.x0 + 1, row), toRgba8(bars[0].scale.map().table().back()));
}

}  // namespace
}  // namespace ejecta::render
