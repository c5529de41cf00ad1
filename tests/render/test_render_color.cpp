// Colour maps against their published tables, Moreland's diverging map against his table, the
// colour scale (linear, log, percentiles, degenerate and invalid ranges) and the annotation
// labels (numbers, time, round scale-bar lengths).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "render/color_scale.hpp"
#include "render/diverging_map.hpp"
#include "render/labels.hpp"

namespace ejecta::render {
namespace {

Rgba8 bytes(const Rgb& c) { return toRgba8(c); }

// viridis and inferno: published float tables (matplotlib's _cm_listed, van der Walt & Smith,
// CC0) at entries 0, 128 and 255, rounded to 8 bits here. The library stores the same rounding,
// so the entries must match exactly.
TEST(RenderColor, ViridisAndInfernoMatchThePublishedTables) {
  const ColorMap viridis(ColorMapName::Viridis), inferno(ColorMapName::Inferno);
  EXPECT_EQ(bytes(viridis.at(0.0)), (Rgba8{68, 1, 84, 255}));  // 0.267004, 0.004874, 0.329415
  EXPECT_EQ(bytes(viridis.at(128.0 / 255.0)), (Rgba8{33, 145, 140, 255}));
  EXPECT_EQ(bytes(viridis.at(1.0)), (Rgba8{253, 231, 37, 255}));  // 0.993248, 0.906157, 0.143936
  EXPECT_EQ(bytes(inferno.at(0.0)), (Rgba8{0, 0, 4, 255}));       // 0.001462, 0.000466, 0.013866
  EXPECT_EQ(bytes(inferno.at(128.0 / 255.0)), (Rgba8{188, 55, 84, 255}));
  EXPECT_EQ(bytes(inferno.at(1.0)), (Rgba8{252, 255, 164, 255}));  // 0.988362, 0.998364, 0.644924
  // Between entries: linear. Halfway from entry 0 to 1 of viridis, (68,1,84)..(68,2,86).
  const Rgb half = viridis.at(0.5 / 255.0);
  EXPECT_NEAR(half.g, 1.5f / 255.0f, 1e-6f);
  EXPECT_NEAR(half.b, 85.0f / 255.0f, 1e-6f);
  // Clamped outside [0, 1].
  EXPECT_EQ(bytes(viridis.at(-3.0)), bytes(viridis.at(0.0)));
  EXPECT_EQ(bytes(viridis.at(7.0)), bytes(viridis.at(1.0)));
  // Perceptual maps rise in lightness monotonically: check luma along the table.
  for (const ColorMap& map : {viridis, inferno}) {
    double previous = -1.0;
    for (const Rgb& c : map.table()) {
      const double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
      EXPECT_GT(luma, previous - 0.01);  // 8-bit rounding wiggles by < 1%
      previous = luma;
    }
  }
}

// Moreland's published cool-warm table (CoolWarmFloat33.csv, from his 2009 paper's map; the
// same numbers are matplotlib's "coolwarm"). Our Msh implementation with his end points must
// reproduce it: the table has 9 significant digits and the method is exact, so 1e-6 leaves
// only the table's rounding.
TEST(RenderColor, CoolWarmReproducesMorelandsTable) {
  struct Row {
    double t, r, g, b;
  };
  const std::array<Row, 9> table{{
      {0.0, 0.229805700, 0.298717966, 0.753683153},
      {0.125, 0.383013340, 0.509419040, 0.917387822},
      {0.25, 0.552953156, 0.688929332, 0.995375608},
      {0.375, 0.722193294, 0.813952739, 0.976574709},
      {0.5, 0.865395197, 0.865410210, 0.865395561},
      {0.625, 0.958852946, 0.769767752, 0.678007945},
      {0.75, 0.958003065, 0.602842431, 0.481775914},
      {0.875, 0.869186849, 0.378313092, 0.300267182},
      {1.0, 0.705673158, 0.015556160, 0.150232812},
  }};
  for (const Row& row : table) {
    const auto c = divergingColor(kCoolWarmCool, kCoolWarmWarm, row.t);
    EXPECT_NEAR(c[0], row.r, 1e-6) << "t = " << row.t;
    EXPECT_NEAR(c[1], row.g, 1e-6) << "t = " << row.t;
    EXPECT_NEAR(c[2], row.b, 1e-6) << "t = " << row.t;
  }
  // Round trip sRGB -> Msh -> sRGB, and the paper's 8-bit end colours (59, 76, 192) and
  // (180, 4, 38) are within a unit of the Msh ends.
  const std::array<double, 3> colour{0.3, 0.6, 0.2};
  const auto back = toSrgb(toMsh(colour));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], colour[k], 1e-4);  // 4-digit matrices
  const ColorMap cw(ColorMapName::CoolWarm);
  EXPECT_NEAR(bytes(cw.at(0.0)).r, 59, 1);
  EXPECT_NEAR(bytes(cw.at(0.0)).b, 192, 1);
  EXPECT_NEAR(bytes(cw.at(1.0)).r, 180, 1);
  EXPECT_NEAR(bytes(cw.at(1.0)).g, 4, 1);
}

TEST(RenderColor, NamesRoundTripAndUnknownNamesAreRejected) {
  for (auto n : {ColorMapName::Viridis, ColorMapName::Inferno, ColorMapName::CoolWarm})
    EXPECT_EQ(colorMapFromName(colorMapName(n)), n);
  try {
    colorMapFromName("jet");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'jet'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("viridis"), std::string::npos);
  }
}

TEST(RenderColor, LinearAndLogScales) {
  const ColorScale linear(ColorMap(), 2.0, 6.0);
  EXPECT_DOUBLE_EQ(linear.normalise(2.0), 0.0);
  EXPECT_DOUBLE_EQ(linear.normalise(3.0), 0.25);
  EXPECT_DOUBLE_EQ(linear.normalise(100.0), 1.0);
  EXPECT_TRUE(std::isnan(linear.normalise(std::nan(""))));
  EXPECT_EQ(linear.color(std::nan("")), ColorScale::kNoData);
  // Log: each decade the same length. 1e3..1e7: 1e4 at 1/4, 1e5 at 1/2.
  const ColorScale log(ColorMap(), 1e3, 1e7, ScaleKind::Log);
  EXPECT_NEAR(log.normalise(1e4), 0.25, 1e-12);
  EXPECT_NEAR(log.normalise(1e5), 0.5, 1e-12);
  EXPECT_NEAR(log.normalise(std::sqrt(10.0) * 1e3), 0.125, 1e-12);
  EXPECT_DOUBLE_EQ(log.normalise(-5.0), 0.0);
  EXPECT_THROW(ColorScale(ColorMap(), 0.0, 1.0, ScaleKind::Log), std::invalid_argument);
  EXPECT_THROW(ColorScale(ColorMap(), 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ColorScale(ColorMap(), 1.0, std::nan("")), std::invalid_argument);
}

TEST(RenderColor, AutomaticRangesAndPercentiles) {
  // 0..100 and one wild value: the full range reaches it, 1st-99th percentiles do not.
  std::vector<double> v;
  for (int i = 0; i <= 100; ++i) v.push_back(i);
  v.push_back(1e9);
  v.push_back(std::nan(""));
  ColorScaleSpec spec;
  ColorScale full = resolveScale(spec, v);
  EXPECT_EQ(full.min(), 0.0);
  EXPECT_EQ(full.max(), 1e9);
  spec.lowPercentile = 1.0;
  spec.highPercentile = 99.0;
  // 102 finite values: the p-th percentile sits at rank p/100 * 101 (linear between ranks).
  ColorScale robust = resolveScale(spec, v);
  EXPECT_NEAR(robust.min(), 1.01, 1e-12);
  EXPECT_NEAR(robust.max(), 99.99, 1e-12);
  // A given end wins over the data.
  spec.max = 50.0;
  EXPECT_EQ(resolveScale(spec, v).max(), 50.0);
  // Log scales ignore values <= 0.
  ColorScaleSpec logSpec;
  logSpec.kind = ScaleKind::Log;
  const std::vector<double> withZeros{0.0, -1.0, 10.0, 1000.0};
  const ColorScale logScale = resolveScale(logSpec, withZeros);
  EXPECT_EQ(logScale.min(), 10.0);
  EXPECT_EQ(logScale.max(), 1000.0);
  // Degenerate data still gives a ramp around the value.
  const std::vector<double> same{4.0, 4.0};
  const ColorScale flat = resolveScale(ColorScaleSpec{}, same);
  EXPECT_EQ(flat.min(), 2.0);
  EXPECT_EQ(flat.max(), 6.0);
  const ColorScale flatLog = resolveScale(logSpec, same);
  EXPECT_NEAR(flatLog.min() * flatLog.max(), 16.0, 1e-12);
  // No data at all.
  const ColorScale nothing = resolveScale(ColorScaleSpec{}, {});
  EXPECT_EQ(nothing.min(), 0.0);
  EXPECT_EQ(nothing.max(), 1.0);
  ColorScaleSpec bad;
  bad.lowPercentile = 60.0;
  bad.highPercentile = 40.0;
  EXPECT_THROW(resolveScale(bad, v), std::invalid_argument);
}

TEST(RenderColor, LabelsAndRoundLengths) {
  EXPECT_EQ(formatNumber(2700.0), "2.7e3");
  EXPECT_EQ(formatNumber(0.00012345), "0.000123");
  EXPECT_EQ(formatNumber(1.5e-7), "1.5e-7");
  EXPECT_EQ(formatNumber(-42.0), "-42");
  EXPECT_EQ(formatNumber(123456.0, 4), "1.235e5");
  EXPECT_EQ(formatTime(1.25e-3), "t = 1.25 ms");
  EXPECT_EQ(formatTime(0.0), "t = 0 s");
  EXPECT_EQ(formatTime(2.5), "t = 2.5 s");
  EXPECT_EQ(formatTime(3.2e-6), "t = 3.2 \xC2\xB5s");
  EXPECT_EQ(formatTime(4e-9), "t = 4 ns");
  EXPECT_EQ(roundLength(7.3), 5.0);
  EXPECT_EQ(roundLength(10.0), 10.0);
  EXPECT_EQ(roundLength(19.9), 10.0);
  EXPECT_EQ(roundLength(0.031), 0.02);
  EXPECT_EQ(roundLength(999.0), 500.0);
  EXPECT_EQ(roundLength(1000.0), 1000.0);
  EXPECT_THROW(roundLength(0.0), std::invalid_argument);
  EXPECT_EQ(formatLength(10.0), "10 m");
  EXPECT_EQ(formatLength(2000.0), "2 km");
  EXPECT_EQ(formatLength(0.5), "500 mm");
  EXPECT_EQ(formatLength(2e-5), "20 \xC2\xB5m");
  EXPECT_EQ(fieldLabel("density", "kg/m^3"), "density [kg/m^3]");
  EXPECT_EQ(fieldLabel("damage", ""), "damage");
}

}  // namespace
}  // namespace ejecta::render
