// Meshes and slices through OSMesa: a spacecraft's faces take their scalar's colour, the
// headlight's Lambert shading of a tilted face, colours interpolated along the map between
// vertices, slice cells and their missing data, the axisymmetric mirror of a slice, cuts, and
// one scene with all three kinds of layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <vector>

#include "render/renderer.hpp"

namespace ejecta::render {
namespace {

constexpr Rgba8 kWhite{255, 255, 255, 255};

::testing::AssertionResult near(Rgba8 got, Rgba8 want, int tolerance) {
  const int d =
      std::max({std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b)});
  if (d <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "got (" << int(got.r) << ", " << int(got.g) << ", " << int(got.b) << "), want ("
         << int(want.r) << ", " << int(want.g) << ", " << int(want.b) << ")";
}

Renderer& renderer() {
  static Renderer r([] {
    RenderSettings s;
    s.width = 200;
    s.height = 100;
    return s;
  }());
  return r;
}

// 200 x 100 pixels showing x in [-5, 5], y in [-2.5, 2.5]: 20 pixels per metre.
View planeView() {
  View v;
  v.center = std::array<double, 2>{0.0, 0.0};
  v.width = 10.0;
  return v;
}
int pixelX(double x) { return static_cast<int>(std::floor((x + 5.0) * 20.0)); }
int pixelY(double y) { return static_cast<int>(std::floor((2.5 - y) * 20.0)); }

Annotations none() {
  Annotations a;
  a.scaleBar = false;
  a.colorBars = false;
  return a;
}

struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // A rectangle [x0, x1] x [y0, y1] at z, as two triangles.
  void quad(double x0, double y0, double x1, double y1, double z = 0.0) {
    const auto base = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}});
    triangles.push_back({base, base + 1, base + 2});
    triangles.push_back({base, base + 2, base + 3});
  }
  MeshLayer layer() const {
    MeshLayer m;
    m.vertices = vertices;
    m.triangles = triangles;
    return m;
  }
};

TEST(RenderMesh, SpacecraftFacesTakeTheirScalarsColour) {
  // Three panels facing the camera (the headlight hits them square on: no darkening), with
  // incident fluxes 1e3, 1e4 and 1e5 W/m^2 on a log scale: the map's start, middle and end.
  Mesh craft;
  craft.quad(-4.0, -1.0, -2.0, 1.0);
  craft.quad(-1.0, -1.0, 1.0, 1.0);
  craft.quad(2.0, -1.0, 4.0, 1.0);
  const std::vector<double> flux{1e3, 1e3, 1e4, 1e4, 1e5, 1e5};  // per triangle
  Picture scene;
  scene.meshes.push_back(craft.layer());
  scene.meshes.back().triangleValues = flux;
  scene.meshes.back().scale.map = ColorMapName::Inferno;
  scene.meshes.back().scale.kind = ScaleKind::Log;
  scene.annotations = none();
  const Frame f = renderer().render(scene, planeView());
  const ColorMap inferno(ColorMapName::Inferno);
  // The LUT is sampled in the shader: float texture, 8-bit output: one unit.
  EXPECT_TRUE(near(f.image.at(pixelX(-3.0), pixelY(0.3)), toRgba8(inferno.at(0.0)), 1));
  EXPECT_TRUE(near(f.image.at(pixelX(0.0), pixelY(-0.3)), toRgba8(inferno.at(0.5)), 1));
  EXPECT_TRUE(near(f.image.at(pixelX(3.0), pixelY(0.5)), toRgba8(inferno.at(1.0)), 1));
  EXPECT_EQ(f.image.at(pixelX(-1.5), pixelY(0.0)), kWhite);  // between panels
  EXPECT_EQ(f.image.at(pixelX(0.0), pixelY(1.5)), kWhite);   // above them
  // A missing value (NaN) is grey.
  std::vector<double> missing = flux;
  missing[2] = missing[3] = std::numeric_limits<double>::quiet_NaN();
  scene.meshes.back().triangleValues = missing;
  const Frame g = renderer().render(scene, planeView());
  EXPECT_TRUE(near(g.image.at(pixelX(0.0), pixelY(0.0)), toRgba8(ColorScale::kNoData), 1));
}

TEST(RenderMesh, HeadlightShadingFollowsLambert) {
  // A white panel turned 60 degrees about y: cos 60 = 1/2 of the light, so 0.2 + 0.8 / 2 = 0.6
  // of white with the 20% ambient term.
  Mesh panel;
  const double c = std::cos(std::numbers::pi / 3.0), s = std::sin(std::numbers::pi / 3.0);
  panel.vertices = {{-2.0 * c, -1.0, -2.0 * s},
                    {2.0 * c, -1.0, 2.0 * s},
                    {2.0 * c, 1.0, 2.0 * s},
                    {-2.0 * c, 1.0, -2.0 * s}};
  panel.triangles = {{0, 1, 2}, {0, 2, 3}};
  Picture scene;
  scene.meshes.push_back(panel.layer());
  scene.meshes.back().color = {1.0f, 1.0f, 1.0f};
  scene.annotations = none();
  RenderSettings settings = renderer().settings();
  settings.background = {0.0f, 0.0f, 0.0f};
  renderer().setSettings(settings);
  const Frame f = renderer().render(scene, planeView());
  settings.background = {1.0f, 1.0f, 1.0f};
  renderer().setSettings(settings);
  EXPECT_NEAR(f.image.at(pixelX(0.2), pixelY(0.2)).r, 0.6 * 255, 1.5);
  // Seen end-on it spans 2 cos 60 = 1 m each side: 20 pixels.
  EXPECT_EQ(f.image.at(pixelX(0.9), pixelY(0.0)).r, f.image.at(pixelX(0.2), pixelY(0.2)).r);
  EXPECT_EQ(f.image.at(pixelX(1.1), pixelY(0.0)).r, 0);
}

TEST(RenderMesh, VertexValuesAreInterpolatedAlongTheMap) {
  // Values 0 at x = -4 and 1 at x = 4: at x = -2 the scalar is 0.25, and the colour is the
  // map's at 0.25, not the RGB blend of its ends (viridis bends through blue-green).
  Mesh strip;
  strip.quad(-4.0, -1.0, 4.0, 1.0);
  const std::vector<double> values{0.0, 1.0, 1.0, 0.0};
  Picture scene;
  scene.meshes.push_back(strip.layer());
  scene.meshes.back().vertexValues = values;
  scene.meshes.back().shaded = false;
  scene.annotations = none();
  const Frame f = renderer().render(scene, planeView());
  const ColorMap viridis;
  // The pixel's centre is at x = -1.975 m: scalar (x + 4) / 8 = 0.2531.
  const double centre = (pixelX(-2.0) + 0.5) / 20.0 - 5.0;
  const Rgba8 want = toRgba8(viridis.at((centre + 4.0) / 8.0));
  EXPECT_TRUE(near(f.image.at(pixelX(-2.0), pixelY(0.0)), want, 1));
  const Rgb a = viridis.at(0.0), b = viridis.at(1.0);
  const Rgba8 blend =
      toRgba8({0.75f * a.r + 0.25f * b.r, 0.75f * a.g + 0.25f * b.g, 0.75f * a.b + 0.25f * b.b});
  EXPECT_FALSE(near(f.image.at(pixelX(-2.0), pixelY(0.0)), blend, 20));
}

TEST(RenderMesh, ClippingPlaneCutsAMesh) {
  Mesh strip;
  strip.quad(-4.0, -1.0, 4.0, 1.0);
  Picture scene;
  scene.meshes.push_back(strip.layer());
  scene.meshes.back().color = {0.0f, 0.0f, 0.0f};
  scene.annotations = none();
  View v = planeView();
  v.clipPlanes.push_back({{1.0, 0.0, 0.0}, 0.5});  // keep x <= 0.5
  const Frame f = renderer().render(scene, v);
  EXPECT_EQ(f.image.at(pixelX(0.4), pixelY(0.0)), (Rgba8{0, 0, 0, 255}));
  EXPECT_EQ(f.image.at(pixelX(0.6), pixelY(0.0)), kWhite);
  EXPECT_EQ(f.image.at(pixelX(3.0), pixelY(0.0)), kWhite);
}

// A 4 x 3 slice of 1 m cells from x = -2, y = -1.5 (cell centres at -1.5 .. 1.5, -1 .. 1):
// each cell is 20 x 20 pixels.
struct Slice {
  std::vector<double> values;
  Slice() {
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) values.push_back(i + 10.0 * j);
    values[1 + 4 * 1] = std::numeric_limits<double>::quiet_NaN();
  }
  SliceLayer layer() const {
    SliceLayer s;
    s.nx = 4;
    s.ny = 3;
    s.values = values;
    s.origin = {-1.5, -1.0, 0.0};
    s.spacing = {1.0, 1.0};
    s.field = "density";
    return s;
  }
};

TEST(RenderMesh, SliceCellsTakeTheirValuesColour) {
  const Slice slice;
  Picture scene;
  scene.slices.push_back(slice.layer());
  scene.annotations = none();
  const Frame f = renderer().render(scene, planeView());
  const ColorScale scale(ColorMap(), 0.0, 23.0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) {
      const double v = slice.values[static_cast<std::size_t>(i + 4 * j)];
      const Rgba8 got = f.image.at(pixelX(-1.5 + i), pixelY(-1.0 + j));
      if (std::isnan(v))
        EXPECT_EQ(got, kWhite) << "no data is transparent";
      else
        EXPECT_EQ(got, toRgba8(scale.color(v))) << i << ", " << j;  // nearest: exact
    }
  // Sharp cell edges: 1 pixel either side of x = -1 belongs to cells 0 and 1.
  const int edge = pixelX(-1.0);
  EXPECT_EQ(f.image.at(edge - 1, pixelY(-1.0)), toRgba8(scale.color(0.0)));
  EXPECT_EQ(f.image.at(edge, pixelY(-1.0)), toRgba8(scale.color(1.0)));
  // Outside the slice: background.
  EXPECT_EQ(f.image.at(pixelX(2.2), pixelY(0.0)), kWhite);
  EXPECT_EQ(f.image.at(pixelX(0.0), pixelY(1.7)), kWhite);
}

TEST(RenderMesh, AxisymmetricSliceIsMirrored) {
  // An RZ slice from the axis: cells at r = 0.5 .. 3.5; mirrored to -r.
  std::vector<double> values{1.0, 2.0, 3.0, 4.0};
  SliceLayer s;
  s.nx = 4;
  s.ny = 1;
  s.values = values;
  s.origin = {0.5, 0.0, 0.0};
  s.spacing = {1.0, 1.0};
  Picture scene;
  scene.slices.push_back(s);
  scene.annotations = none();
  View v = planeView();
  v.kind = ViewKind::Axisymmetric;
  const Frame f = renderer().render(scene, v);
  const ColorScale scale(ColorMap(), 1.0, 4.0);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(f.image.at(pixelX(0.5 + i), pixelY(0.0)), toRgba8(scale.color(values[i])));
    EXPECT_EQ(f.image.at(pixelX(-0.5 - i), pixelY(0.0)), toRgba8(scale.color(values[i])));
  }
}

TEST(RenderMesh, OneSceneWithParticlesMeshAndSlice) {
  const Slice slice;
  Mesh craft;
  craft.quad(3.0, -2.0, 4.5, 2.0);
  const std::vector<double> temperature{400.0, 900.0};
  const std::vector<double> x{-1.5}, y{-1.0}, h{0.4}, rho{2700.0};
  Picture scene;
  scene.slices.push_back(slice.layer());
  scene.meshes.push_back(craft.layer());
  scene.meshes.back().triangleValues = temperature;
  scene.meshes.back().field = "wall temperature";
  scene.meshes.back().units = "K";
  ParticleLayer particles;
  particles.x = x;
  particles.y = y;
  particles.h = h;
  particles.values = rho;
  particles.style = ParticleStyle::Flat;
  particles.scale.map = ColorMapName::CoolWarm;
  particles.field = "density";
  scene.particles.push_back(particles);
  RenderSettings settings = renderer().settings();
  settings.height = 260;  // room for the strip with three colour bars
  renderer().setSettings(settings);
  View v = planeView();
  const Frame f = renderer().render(scene, v);
  settings.height = 100;
  renderer().setSettings(settings);
  ASSERT_EQ(f.colorBars.size(), 3u);
  EXPECT_EQ(f.colorBars[0].label, "density");
  EXPECT_EQ(f.colorBars[1].label, "wall temperature [K]");
  EXPECT_EQ(f.strip.colorBars.size(), 3u);
  // The particle is drawn over the slice cell under it (later layers win at equal depth).
  const auto p = f.framing.project({-1.5, -1.0, 0.0});
  const ColorScale single = resolveScale(particles.scale, rho);
  EXPECT_EQ(f.image.at(static_cast<int>(p[0]), static_cast<int>(p[1])),
            toRgba8(single.color(2700.0)));
  // The mesh's two triangles: 400 K and 900 K, the ends of its own scale.
  const ColorMap viridis;
  const auto upper = f.framing.project({3.5, 1.5, 0.0});   // triangle 1 (x0,y0)-(x1,y1)-(x0,y1)
  const auto lower = f.framing.project({4.2, -1.5, 0.0});  // triangle 0
  EXPECT_TRUE(near(f.image.at(static_cast<int>(upper[0]), static_cast<int>(upper[1])),
                   toRgba8(viridis.at(1.0)), 1));
  EXPECT_TRUE(near(f.image.at(static_cast<int>(lower[0]), static_cast<int>(lower[1])),
                   toRgba8(viridis.at(0.0)), 1));
}

TEST(RenderMesh, RejectsBadMeshesAndSlices) {
  Mesh bad;
  bad.quad(0.0, 0.0, 1.0, 1.0);
  bad.triangles.push_back({0, 1, 9});
  Picture scene;
  scene.meshes.push_back(bad.layer());
  try {
    renderer().render(scene, planeView());
    FAIL();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mesh layer 0"), std::string::npos) << what;
    EXPECT_NE(what.find("triangle 2 uses vertex 9"), std::string::npos) << what;
  }
  Picture slices;
  const Slice slice;
  slices.slices.push_back(slice.layer());
  slices.slices.back().nx = 5;
  EXPECT_THROW(renderer().render(slices, planeView()), std::invalid_argument);
  View tooMany = planeView();
  tooMany.clipPlanes.resize(5);
  EXPECT_THROW(renderer().render(Picture{}, tooMany), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::render
