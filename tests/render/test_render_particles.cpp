// Particles drawn through OSMesa: where a particle lands (orientation +x right, +y up), the
// axisymmetric mirror, perspective and clipping planes, colours on linear and log scales,
// shading, auto-fit, and the annotation strip (colour-bar ends, time label, scale bar).
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "render/labels.hpp"
#include "render/renderer.hpp"

namespace ejecta::render {
namespace {

// Published 8-bit viridis entries (matplotlib's table, van der Walt & Smith): 0, 85 (t = 1/3)
// and 255.
constexpr Rgba8 kViridis0{68, 1, 84, 255};
constexpr Rgba8 kViridis85{49, 104, 142, 255};
constexpr Rgba8 kViridis255{253, 231, 37, 255};
constexpr Rgba8 kWhite{255, 255, 255, 255};

// A particle's colour after the 8-bit round trip through OpenGL: llvmpipe's fixed-point
// colour path may differ from the CPU's rounding by one unit.
::testing::AssertionResult near(Rgba8 got, Rgba8 want, int tolerance = 1) {
  const int d =
      std::max({std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b)});
  if (d <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "got (" << int(got.r) << ", " << int(got.g) << ", " << int(got.b) << "), want ("
         << int(want.r) << ", " << int(want.g) << ", " << int(want.b) << ")";
}

Annotations none() {
  Annotations a;
  a.scaleBar = false;
  a.colorBars = false;
  return a;
}

RenderSettings size(int w, int h) {
  RenderSettings s;
  s.width = w;
  s.height = h;
  return s;
}

// Shared by the tests: one context for the whole file (creating one takes tens of ms).
Renderer& renderer() {
  static Renderer r(size(200, 100));
  return r;
}

struct Particles {
  std::vector<double> x, y, z, h, values;
  ParticleLayer layer(ParticleStyle style = ParticleStyle::Flat) const {
    ParticleLayer p;
    p.x = x;
    p.y = y;
    p.z = z;
    p.h = h;
    p.values = values;
    p.style = style;
    return p;
  }
};

int inkCount(const Image& image, int x0, int y0, int x1, int y1, Rgba8 background) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (image.contains(x, y) && image.at(x, y) != background) ++n;
  return n;
}

// A 10 m wide plane view of a 200 x 100 image: 20 pixels per metre, the view centred on the
// origin. A point at pixel centre (i + 1/2, j + 1/2) has x = (i + 0.5) / 20 - 5 and
// y = 2.5 - (j + 0.5) / 20 (+y up: row 0 is the top).
double worldX(int i) { return (i + 0.5) / 20.0 - 5.0; }
double worldY(int j) { return 2.5 - (j + 0.5) / 20.0; }

View planeView() {
  View v;
  v.kind = ViewKind::Plane;
  v.center = std::array<double, 2>{0.0, 0.0};
  v.width = 10.0;
  return v;
}

TEST(RenderParticles, LandOnTheExpectedPixelWithYUp) {
  Renderer& r = renderer();
  r.setSettings(size(200, 100));
  // h = 0.5 m, disc radius h/2 = 0.25 m = 5 pixels.
  Particles p{{worldX(150)}, {worldY(25)}, {}, {0.5}, {}};
  Picture scene;
  scene.particles.push_back(p.layer());
  scene.particles.back().color = {1.0f, 0.0f, 0.0f};
  scene.annotations = none();
  const Frame f = r.render(scene, planeView());
  ASSERT_EQ(f.image.width(), 200);
  ASSERT_EQ(f.image.height(), 100);
  const Rgba8 red{255, 0, 0, 255};
  EXPECT_EQ(f.image.at(150, 25), red);
  // Inside the 5-pixel radius in every direction, outside beyond it.
  for (auto [dx, dy] : {std::pair{3, 0}, {-3, 0}, {0, 3}, {0, -3}})
    EXPECT_EQ(f.image.at(150 + dx, 25 + dy), red);
  for (auto [dx, dy] : {std::pair{7, 0}, {-7, 0}, {0, 7}, {0, -7}, {5, 5}})
    EXPECT_EQ(f.image.at(150 + dx, 25 + dy), kWhite);
  // The disc's ink is about pi 5^2 = 79 pixels, and nothing else is drawn anywhere.
  const int ink = inkCount(f.image, 0, 0, 200, 100, kWhite);
  EXPECT_GT(ink, 60);
  EXPECT_LT(ink, 100);
  EXPECT_EQ(inkCount(f.image, 0, 0, 140, 100, kWhite), 0);
  EXPECT_EQ(inkCount(f.image, 0, 40, 200, 100, kWhite), 0);
  // The framing reports the same place.
  const auto px = f.framing.project({worldX(150), worldY(25), 0.0});
  EXPECT_NEAR(px[0], 150.5, 1e-9);
  EXPECT_NEAR(px[1], 25.5, 1e-9);
}

TEST(RenderParticles, AxisymmetricViewMirrorsAboutTheAxis) {
  Renderer& r = renderer();
  r.setSettings(size(200, 100));
  Particles p{{worldX(150)}, {worldY(70)}, {}, {0.5}, {}};  // r = 2.525 m, z = -1.025 m
  Picture scene;
  scene.particles.push_back(p.layer());
  scene.particles.back().color = {0.0f, 0.0f, 1.0f};
  scene.annotations = none();
  View v = planeView();
  v.kind = ViewKind::Axisymmetric;
  const Frame f = r.render(scene, v);
  const Rgba8 blue{0, 0, 255, 255};
  EXPECT_EQ(f.image.at(150, 70), blue);  // at +r
  EXPECT_EQ(f.image.at(49, 70), blue);   // and its mirror image at -r: pixel 199 - 150
  EXPECT_EQ(f.image.at(100, 70), kWhite);
  EXPECT_EQ(inkCount(f.image, 60, 0, 140, 100, kWhite), 0);
  // The same particle in a plane view has no mirror image.
  const Frame plane = r.render(scene, planeView());
  EXPECT_EQ(plane.image.at(49, 70), kWhite);
  EXPECT_EQ(plane.image.at(150, 70), blue);
}

TEST(RenderParticles, PerspectiveProjectionAndAClippingPlaneCut) {
  Renderer& r = renderer();
  r.setSettings(size(200, 200));
  // Camera on the +z axis 10 m out, 90 degrees: a point (x, 0, z) lands at
  // pixel x = 100 (1 + x / (10 - z)).
  // Discs of radius 1 m: 2 * 1 m * 100 px / distance across, 18.2 and 22.2 pixels.
  Particles p{{-1.0, 1.0}, {0.0, 0.0}, {-1.0, 1.0}, {2.0, 2.0}, {}};
  Picture scene;
  scene.particles.push_back(p.layer());
  scene.particles.back().color = {0.0f, 0.5f, 0.0f};
  scene.annotations = none();
  View v;
  v.kind = ViewKind::Perspective;
  v.camera = Camera{{0.0, 0.0, 10.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 90.0};
  const Frame whole = r.render(scene, v);
  const int kept = static_cast<int>(100.0 * (1.0 - 1.0 / 11.0));  // 90.9: pixel 90
  const int cut = static_cast<int>(100.0 * (1.0 + 1.0 / 9.0));    // 111.1: pixel 111
  const Rgba8 green = toRgba8({0.0f, 0.5f, 0.0f});
  EXPECT_EQ(whole.image.at(kept, 100), green);
  EXPECT_EQ(whole.image.at(cut, 100), green);
  // The nearer disc looks bigger by the square of the distance ratio, (11/9)^2 = 1.49 in area
  // (the pixelated discs of 260 and 390 pixels: a few percent).
  const int nearInk = inkCount(whole.image, 100, 80, 130, 120, kWhite);
  const int farInk = inkCount(whole.image, 70, 80, 100, 120, kWhite);
  EXPECT_NEAR(nearInk / static_cast<double>(farInk), (11.0 * 11.0) / (9.0 * 9.0), 0.08);
  v.clipPlanes.push_back({{0.0, 0.0, 1.0}, 0.0});  // keep z <= 0
  const Frame half = r.render(scene, v);
  EXPECT_EQ(half.image.at(kept, 100), green);
  EXPECT_EQ(half.image.at(cut, 100), kWhite);
  EXPECT_EQ(inkCount(half.image, 101, 0, 200, 200, kWhite), 0);
}

TEST(RenderParticles, LogScaleGivesEachDecadeAnEqualShareOfTheMap) {
  Renderer& r = renderer();
  r.setSettings(size(200, 100));
  // Values 1, 10, 100, 1000 at four places; log scale over [1, 1000]: 10 sits at t = 1/3,
  // which is exactly viridis entry 85.
  Particles p{{worldX(20), worldX(70), worldX(120), worldX(170)},
              {worldY(50), worldY(50), worldY(50), worldY(50)},
              {},
              {0.5, 0.5, 0.5, 0.5},
              {1.0, 10.0, 100.0, 1000.0}};
  Picture scene;
  scene.particles.push_back(p.layer());
  scene.particles.back().scale.kind = ScaleKind::Log;
  scene.annotations = none();
  const Frame f = r.render(scene, planeView());
  EXPECT_TRUE(near(f.image.at(20, 50), kViridis0));
  EXPECT_TRUE(near(f.image.at(70, 50), kViridis85));
  EXPECT_TRUE(near(f.image.at(170, 50), kViridis255));
  // On a linear scale the same value sits at t = 9/999, nearly the map's start.
  scene.particles.back().scale.kind = ScaleKind::Linear;
  const Frame linear = r.render(scene, planeView());
  const Rgba8 startish = toRgba8(ColorMap(ColorMapName::Viridis).at(9.0 / 999.0));
  EXPECT_TRUE(near(linear.image.at(70, 50), startish));
  EXPECT_FALSE(near(linear.image.at(70, 50), kViridis85, 10));
}

TEST(RenderParticles, ShadedDiscsAreBrightestInTheMiddle) {
  Renderer& r = renderer();
  r.setSettings(size(200, 100));
  Particles p{{worldX(100)}, {worldY(50)}, {}, {2.0}, {}};  // radius 1 m = 20 pixels
  Picture scene;
  scene.particles.push_back(p.layer(ParticleStyle::Shaded));
  scene.particles.back().color = {1.0f, 1.0f, 1.0f};
  scene.annotations = none();
  RenderSettings s = size(200, 100);
  s.background = {0.0f, 0.0f, 0.0f};
  r.setSettings(s);
  const Frame f = r.render(scene, planeView());
  const int centre = f.image.at(100, 50).r;
  const int edge = f.image.at(118, 50).r;  // 18 of 20 pixels out: normal ~ 0.42 towards us
  EXPECT_GE(centre, 250);
  // 0.25 + 0.75 sqrt(1 - r^2) at r = 17.5/20 .. 18.5/20: 0.53 .. 0.61 of full.
  EXPECT_GT(edge, 0.50 * 255);
  EXPECT_LT(edge, 0.64 * 255);
  EXPECT_EQ(f.image.at(122, 50).r, 0);
}

TEST(RenderParticles, AutoFitShowsEveryParticle) {
  Renderer& r = renderer();
  r.setSettings(size(200, 100));
  // A spread of particles far from the origin; no centre or width given.
  Particles p{{1000.0, 1040.0, 1010.0}, {-500.0, -480.0, -470.0}, {}, {1.0, 1.0, 1.0}, {}};
  Picture scene;
  scene.particles.push_back(p.layer());
  scene.particles.back().color = {0.0f, 0.0f, 0.0f};
  scene.annotations = none();
  View v;
  const Frame f = r.render(scene, v);
  // The box with the 0.5 m disc radii is 41 x 31 m; in a 2:1 picture the height binds:
  // width 2 x 31 m, plus the 6% margin.
  EXPECT_NEAR(200.0 / f.framing.pixelsPerMetre, 62.0 * 1.06, 1e-9);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto px = f.framing.project({p.x[i], p.y[i], 0.0});
    ASSERT_GT(px[0], 0.0);
    ASSERT_LT(px[0], 200.0);
    ASSERT_GT(px[1], 0.0);
    ASSERT_LT(px[1], 100.0);
    EXPECT_EQ(f.image.at(static_cast<int>(px[0]), static_cast<int>(px[1])), (Rgba8{0, 0, 0, 255}));
  }
}

TEST(RenderParticles, ColourBarEndsAreTheMapsEndColours) {
  Renderer& r = renderer();
  r.setSettings(size(400, 300));
  Particles p{{0.0, 1.0}, {0.0, 1.0}, {}, {0.5, 0.5}, {2.0, 7.0}};
  Picture scene;
  scene.particles.push_back(p.layer());
  scene.particles.back().field = "density";
  scene.particles.back().units = "kg/m^3";
  scene.annotations.time = 1.25e-3;
  const Frame f = r.render(scene, View{});
  ASSERT_EQ(f.strip.colorBars.size(), 1u);
  const ColorBarPlacement& bar = f.strip.colorBars[0];
  const int row = (bar.bar.y0 + bar.bar.y1) / 2;
  EXPECT_EQ(f.image.at(bar.bar.x0, row), kViridis0);
  EXPECT_EQ(f.image.at(bar.bar.x1 - 1, row), kViridis255);
  EXPECT_EQ(bar.labelText, "density [kg/m^3]");
  // Round ticks of the range 2 .. 7 (step 1), every one labelled at this width.
  std::vector<std::string> texts;
  for (const ColorBarTick& t : bar.ticks) texts.push_back(t.text);
  EXPECT_EQ(texts, (std::vector<std::string>{"2", "3", "4", "5", "6", "7"}));
  EXPECT_EQ(bar.ticks.front().x, bar.bar.x0);
  EXPECT_EQ(bar.ticks.back().x, bar.bar.x1 - 1);
  // The strip is under the picture and the picture keeps its framing above it.
  EXPECT_EQ(f.strip.top, f.framing.plotHeight);
  EXPECT_EQ(f.strip.top + f.strip.height, 300);
  // The time label is written, and in ink.
  EXPECT_EQ(f.strip.timeText, "t = 1.25 ms");
  const PixelRect& t = f.strip.time;
  EXPECT_GT(inkCount(f.image, t.x0, t.y0, t.x1, t.y1, kWhite), 20);
  // A round scale bar about a fifth of the view.
  EXPECT_GT(f.strip.scaleMetres * f.framing.pixelsPerMetre, 400 / 5.0 / 2.5 - 1);
  EXPECT_LE(f.strip.scaleMetres * f.framing.pixelsPerMetre, 400 / 5.0 + 1);
  EXPECT_EQ(f.strip.scaleText, formatLength(f.strip.scaleMetres));
  EXPECT_GT(inkCount(f.image, f.strip.scaleBar.x0, f.strip.scaleBar.y0, f.strip.scaleBar.x1,
                     f.strip.scaleBar.y1, kWhite),
            f.strip.scaleBar.width());
}

TEST(RenderParticles, SameImageForAnyOpenMPThreadCount) {
  // The CPU side (colours, extent) runs on OpenMP threads; llvmpipe keeps primitive order in
  // every tile. 2000 overlapping particles with random values: any reordering would show.
  Renderer& r = renderer();
  r.setSettings(size(200, 100));
  Particles p;
  unsigned state = 1;
  auto next = [&state] {
    state = state * 1103515245u + 12345u;
    return (state >> 8) / 16777216.0;
  };
  for (int i = 0; i < 2000; ++i) {
    p.x.push_back(8.0 * next() - 4.0);
    p.y.push_back(4.0 * next() - 2.0);
    p.z.push_back(0.0);
    p.h.push_back(0.3 + 0.3 * next());
    p.values.push_back(next());
  }
  Picture scene;
  scene.particles.push_back(p.layer(ParticleStyle::Shaded));
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Frame one = r.render(scene, View{});
  omp_set_num_threads(2);
  const Frame two = r.render(scene, View{});
  const Frame again = r.render(scene, View{});
  omp_set_num_threads(threads);
  EXPECT_EQ(one.image.bytes(), two.image.bytes());
  EXPECT_EQ(two.image.bytes(), again.image.bytes());
}

TEST(RenderParticles, RejectsInconsistentLayers) {
  Renderer& r = renderer();
  r.setSettings(size(200, 100));
  Particles p{{0.0, 1.0}, {0.0, 1.0}, {}, {0.5}, {}};
  Picture scene;
  scene.particles.push_back(p.layer());
  try {
    r.render(scene, View{});
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("particle layer 0"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1 h"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ejecta::render

namespace ejecta::render {
namespace {

TEST(RenderParticles, DistanceAxesTickRoundLengthsAtTheirPixels) {
  // Two particles 10 m apart: a plane view about 10 m wide, ticks every 2 m along the bottom
  // and the left edges, each mark at the pixel its length projects to.
  Renderer& r = renderer();
  r.setSettings(size(400, 400));
  Particles p{{0.0, 10.0}, {0.0, 10.0}, {}, {0.2, 0.2}, {}};
  Picture scene;
  scene.particles.push_back(p.layer());
  scene.annotations.axes = true;
  scene.annotations.scaleBar = false;
  const Frame f = r.render(scene, View{});
  const Rgba8 ink{0, 0, 0, 255};
  for (const double metres : {2.0, 4.0, 6.0, 8.0}) {
    const auto at = f.framing.project({metres, 0.0, 0.0});
    const int column = static_cast<int>(std::lround(at[0]));
    int marked = 0;
    for (int dx = -1; dx <= 1; ++dx) marked += f.image.at(column + dx, f.framing.plotHeight - 2) == ink;
    EXPECT_GT(marked, 0) << metres << " m at column " << column;
    const auto up = f.framing.project({0.0, metres, 0.0});
    const int row = static_cast<int>(std::lround(up[1]));
    marked = 0;
    for (int dy = -1; dy <= 1; ++dy) marked += f.image.at(1, row + dy) == ink;
    EXPECT_GT(marked, 0) << metres << " m at row " << row;
  }
  // Off by default: the bottom row between ticks and under them is background.
  scene.annotations.axes = false;
  const Frame plain = r.render(scene, View{});
  const int column = static_cast<int>(std::lround(plain.framing.project({4.0, 0.0, 0.0})[0]));
  EXPECT_NE(plain.image.at(column, plain.framing.plotHeight - 2), ink);
}

}  // namespace
}  // namespace ejecta::render
