// Occluders and voxel emitters (radiation/view_factors.hpp, thermal_study.hpp, emitters.hpp):
// an emitter sphere seen from a differential element past an opaque plate (fully hidden, half
// hidden, cut by an off-centre edge: exact cosine-weighted solid angles), a plate that is not in
// the way changing nothing, the same through the thermal chain, and hot voxels as emitter
// spheres: their sizes, mixed emissivities and groups, and a thick hot slab of them against the
// exact view factor of its face.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "radiation/constants.hpp"
#include "radiation/emitters.hpp"
#include "radiation/spacecraft.hpp"
#include "radiation/thermal_study.hpp"
#include "radiation/view_factors.hpp"

namespace ejecta::radiation {
namespace {

constexpr double kPi = std::numbers::pi;

// The reference geometry: a receiving element at the origin facing +z, an emitter sphere of
// radius a centred on its normal at height d (a/d = 0.25). Unoccluded, F = (a/d)^2 (Modest
// D-18: a sphere wholly above an element's horizon). Occluding plates lie in the plane z = c.
constexpr double kA = 0.5, kD = 2.0, kC = 1.0;

Emitters oneSphere() {
  Emitters e;
  e.add(0.0, 0.0, kD, kA, 2000.0, 0.5, "melt");
  return e;
}

// The plate {x in [x0, x1], y in [-4, 4], z = c}, facing the element (-z): an occluder.
TriangleMesh plate(double x0, double x1, double c = kC) {
  return makeRectangle("plate", {x0, -4.0, c}, {0.0, 8.0, 0.0}, {x1 - x0, 0.0, 0.0});
}

constexpr std::uint64_t kRays = 1u << 20;

ReceiverResult fromElement(const RadiationScene& scene, std::uint64_t rays = kRays) {
  const ViewFactorSolver solver(scene);
  SamplingOptions o;
  o.rays = rays;
  return solver.fromPoint({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, o);
}

RadiationScene sceneWith(const TriangleMesh& occluder) {
  RadiationScene s;
  s.emitters = oneSphere();
  s.occluder.mesh = occluder;
  return s;
}

// The cosine-weighted measure of the directions to the sphere that pass x = c u/w >= e at the
// plate's plane (u, v, w: the direction's components). By Nusselt's analogue, F = (1/pi) x the
// area of those directions projected onto the unit disc: the disc u^2 + v^2 <= s^2 (s = a/d,
// the sphere's cone) cut by u >= t w = t sqrt(1 - u^2 - v^2), t = e/c, i.e. for t >= 0,
// u >= t sqrt((1 - v^2) / (1 + t^2)). The two boundaries meet at v* = sqrt(s^2 (1 + t^2) - t^2).
// With v = v* sin(phi) the integrand is smooth on [-pi/2, pi/2] (no square-root end points, also
// at t = 0 where v* = s), and Simpson's rule with 2000 intervals is exact to rounding.
double visibleFactorPastEdge(double e) {
  const double s = kA / kD, t = e / kC;
  const double vStar = std::sqrt(s * s * (1.0 + t * t) - t * t);
  auto integrand = [&](double phi) {
    const double v = vStar * std::sin(phi);
    const double width = std::sqrt(std::max(0.0, s * s - v * v)) - t * std::sqrt((1.0 - v * v) / (1.0 + t * t));
    return width * vStar * std::cos(phi);
  };
  const int n = 2000;
  const double h = kPi / n;
  double sum = integrand(-0.5 * kPi) + integrand(0.5 * kPi);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(-0.5 * kPi + i * h);
  return sum * h / 3.0 / kPi;
}

TEST(Occlusion, PlateBetweenElementAndSphere) {
  const double exact = (kA / kD) * (kA / kD);
  const Estimate open = fromElement(sceneWith({})).toGroup[0];
  // Exact geometry (an Embree sphere): only the Monte Carlo error; 4 standard errors (t with 15
  // degrees of freedom, p ~ 1e-3), plus one ray in kRays: the cone and the half plane below map
  // to dyadic boxes of the direction sampler's unit square (the concentric map takes the disc
  // of radius a/d to a square), where the scrambled Sobol' net counts exactly and every
  // replicate agrees (standard error 0).
  const double oneRay = 1.0 / static_cast<double>(kRays);
  EXPECT_NEAR(open.value, exact, 4.0 * open.standardError + oneRay);

  // Fully hidden: the plate covers the sphere's whole cone (radius c tan(asin(a/d)) = 0.26 m at
  // z = c). Not one ray reaches the sphere: F and the flux are exactly 0. The plate fills the
  // view of the element to a square's extent: F to it = 4 x Howell B-3 (element to a parallel
  // rectangle with a corner above it), X = Y = 4/c.
  const ReceiverResult hidden = fromElement(sceneWith(plate(-4.0, 4.0)));
  EXPECT_EQ(hidden.toGroup[0].value, 0.0);
  EXPECT_EQ(hidden.toEmitters.value, 0.0);
  EXPECT_EQ(hidden.flux.value, 0.0);
  const double X = 4.0 / kC;
  const double corner = 1.0 / (2.0 * kPi) *
                        (2.0 * X / std::sqrt(1.0 + X * X) * std::atan(X / std::sqrt(1.0 + X * X)));
  EXPECT_NEAR(hidden.toOccluder.value, 4.0 * corner, 4.0 * hidden.toOccluder.standardError + 1e-12);

  // Half hidden: the plate's edge on the axis (x < 0 covered). The cosine-weighted directions
  // are symmetric under x -> -x, so exactly half the sphere's factor: (a/d)^2 / 2.
  const Estimate half = fromElement(sceneWith(plate(-4.0, 0.0))).toGroup[0];
  EXPECT_NEAR(half.value, 0.5 * exact, 4.0 * half.standardError + oneRay);
  EXPECT_LE(half.standardError, 0.01 * half.value);

  // Cut by an off-centre edge (x < 0.1 m covered at z = c): the exact factor of what is left.
  const double e = 0.1, cut = visibleFactorPastEdge(e);
  const Estimate past = fromElement(sceneWith(plate(-4.0, e))).toGroup[0];
  EXPECT_NEAR(past.value, cut, 4.0 * past.standardError);
  EXPECT_LT(past.standardError, 0.02 * past.value);
  // The quadrature: at e = 0 it gives the half factor.
  EXPECT_NEAR(visibleFactorPastEdge(0.0), 0.5 * exact, 1e-12);
  std::printf("sphere F: open %.6f (exact %.6f); half %.6f +- %.1e (exact %.6f); past x = %.1f: %.6f +- %.1e "
              "(exact %.6f); hidden %g\n",
              open.value, exact, half.value, half.standardError, 0.5 * exact, e, past.value, past.standardError,
              cut, hidden.toGroup[0].value);
}

TEST(Occlusion, PlateOutOfTheWayChangesNothing) {
  // Behind the sphere (z = 3 > d + a) and beside its cone (x in [1, 3] at z = c, where the cone
  // reaches |x| <= 0.26 m): every ray that reached the sphere still does, first. The same rays are
  // cast (same seed, same receiver), so F and the flux are equal to the last bit; the plates do
  // catch rays that missed the sphere (toOccluder > 0).
  const ReceiverResult open = fromElement(sceneWith({}), 1u << 18);
  for (const TriangleMesh& p : {plate(-4.0, 4.0, 3.0), plate(1.0, 3.0)}) {
    const ReceiverResult r = fromElement(sceneWith(p), 1u << 18);
    EXPECT_EQ(r.toGroup[0].value, open.toGroup[0].value);
    EXPECT_EQ(r.toGroup[0].standardError, open.toGroup[0].standardError);
    EXPECT_EQ(r.flux.value, open.flux.value);
    EXPECT_GT(r.toOccluder.value, 0.01);
    EXPECT_LT(r.toSpace.value, open.toSpace.value);
  }
}

// A 0.4 m box over the origin, side0 facing down (-y) at height 1.5 m (as in
// test_radiation_thermal_study.cpp), static for two samples.
ThermalStudy boxStudy() {
  const std::string text =
      "[study]\nname = \"occluded\"\n"
      "[spacecraft]\nshape = \"box\"\nsize = [0.4, 0.4, 0.4]\nforward = [0.0, -1.0, 0.0]\nup = [1.0, 0.0, 0.0]\n"
      "[approach]\nstart = [0.0, 1.7, 0.0]\nvelocity = [0.0, 0.0, 0.0]\nduration = \"1 ms\"\nsamples = 2\n"
      "[sampling]\nrays = 65536\n";
  return parseThermalStudy(text, "occluded.toml", ".");
}

double side0Flux(const ThermalResult& r, std::size_t sample) {
  for (const PatchThermal& p : r.patches)
    if (p.patch == "side0") return p.flux[sample].value;
  throw std::runtime_error("no side0");
}

TEST(Occlusion, ThermalStudyWithAnOccluder) {
  const ThermalStudy study = boxStudy();
  Emitters e;
  e.add(0.0, 0.0, 0.0, 0.3, 3000.0, 0.45, "melt");
  const ThermalResult plain = runThermalStudy(study, e);
  const ThermalResult none = runThermalStudy(study, e, nullptr);
  ASSERT_GT(side0Flux(plain, 0), 0.0);
  EXPECT_EQ(side0Flux(none, 0), side0Flux(plain, 0));  // the overload without an occluder
  EXPECT_EQ(none.occluderTriangles, 0u);

  // A 4 m square plate at y = 0.8, between the sphere (top at 0.3) and side0 (1.5): side0 sees
  // nothing hot, at every sample; the plate fills most of its view.
  const TriangleMesh between = makeRectangle("rock", {-2.0, 0.8, -2.0}, {4.0, 0.0, 0.0}, {0.0, 0.0, 4.0});
  const ThermalResult hidden = runThermalStudy(study, e, &between);
  EXPECT_EQ(hidden.occluderTriangles, 2u);
  for (const PatchThermal& p : hidden.patches) {
    for (const Estimate& q : p.flux) EXPECT_EQ(q.value, 0.0) << p.patch;
    ASSERT_EQ(p.toOccluder.size(), 2u);
  }
  for (const PatchThermal& p : hidden.patches) {
    if (p.patch == "side0") {
      EXPECT_GT(p.peakOccluderFactor, 0.5);
    }
  }
  const std::string json = formatThermalJson(hidden);
  EXPECT_NE(json.find("\"occluder_triangles\": 2"), std::string::npos) << json;
  EXPECT_NE(json.find("occluder_view_factor_at_peak"), std::string::npos);

  // Below the sphere instead: nothing changes on the faces that see the sphere.
  const TriangleMesh below = makeRectangle("rock", {-2.0, -0.5, -2.0}, {4.0, 0.0, 0.0}, {0.0, 0.0, 4.0});
  const ThermalResult under = runThermalStudy(study, e, &below);
  EXPECT_EQ(side0Flux(under, 0), side0Flux(plain, 0));
  EXPECT_EQ(side0Flux(under, 1), side0Flux(plain, 1));

  // A malformed occluder is refused.
  TriangleMesh bad = between;
  bad.triangles[0][0] = 99;
  EXPECT_THROW(runThermalStudy(study, e, &bad), MeshError);
}

TEST(VoxelEmitters, SpheresOfTheMaterialEachVoxelHolds) {
  const double v = 0.008;  // 0.2 m voxels
  const std::vector<double> x{0.0, 1.0, 2.0, 3.0, 4.0}, y(5, 0.0), z(5, 0.0);
  const std::vector<double> T{1499.0, 1500.0, 2000.0, 2500.0, 3000.0};
  // Plain fractions of two materials: their sum is the filled fraction S.
  const std::vector<double> rock{0.9, 0.9, 0.3, 0.0, 0.6}, iron{0.0, 0.0, 0.2, 0.0, 0.7};
  VoxelEmitterSource s;
  s.x = x;
  s.y = y;
  s.z = z;
  s.temperature = T;
  s.voxelVolume = v;
  s.fraction = {rock, iron};
  s.fractionsAreFill = true;
  EmitterSelection sel;  // 1500 K
  sel.emissivityByMaterial = {0.4, 0.8};
  sel.materialNames = {"rock", "iron"};
  const Emitters e = selectVoxelEmitters(s, sel);
  // 1499 K is cold; the 2500 K voxel holds no material; the rest are kept (>= is inclusive).
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e.x[0], 1.0);
  EXPECT_EQ(e.x[1], 2.0);
  EXPECT_EQ(e.x[2], 4.0);
  // Radii: spheres of S v, S capped at 1.
  EXPECT_DOUBLE_EQ(e.radius[0], equalVolumeRadius(0.9 * v));
  EXPECT_DOUBLE_EQ(e.radius[1], equalVolumeRadius(0.5 * v));
  EXPECT_DOUBLE_EQ(e.radius[2], equalVolumeRadius(v));
  EXPECT_NEAR(e.radius[2], 0.6204 * 0.2, 1e-4);  // (3/(4 pi))^(1/3) a
  // Emissivity: the fraction-weighted mean; group: the larger fraction.
  EXPECT_DOUBLE_EQ(e.emissivity[0], 0.4);
  EXPECT_DOUBLE_EQ(e.emissivity[1], (0.3 * 0.4 + 0.2 * 0.8) / 0.5);
  EXPECT_DOUBLE_EQ(e.emissivity[2], (0.6 * 0.4 + 0.7 * 0.8) / 1.3);
  EXPECT_EQ(e.groupNames[e.group[0]], "rock");
  EXPECT_EQ(e.groupNames[e.group[1]], "rock");
  EXPECT_EQ(e.groupNames[e.group[2]], "iron");
  EXPECT_EQ(e.temperature[1], 2000.0);

  // Shares (Shepard-normalised fractions): every kept voxel is full.
  s.fractionsAreFill = false;
  const Emitters full = selectVoxelEmitters(s, sel);
  ASSERT_EQ(full.size(), 3u);
  for (double r : full.radius) EXPECT_DOUBLE_EQ(r, equalVolumeRadius(v));
  // No fractions: full voxels of material 0 with the default emissivity (granite 0.45).
  s.fraction.clear();
  const Emitters bare = selectVoxelEmitters(s, {});
  ASSERT_EQ(bare.size(), 4u);
  EXPECT_EQ(bare.emissivity[0], kGraniteEmissivity);
  EXPECT_EQ(bare.groupNames.at(0), "material0");

  // Bad input names the array and the voxel.
  s.fraction = {rock, iron};
  const std::vector<double> shortIron{0.0, 0.0};
  s.fraction[1] = shortIron;
  EXPECT_THROW(selectVoxelEmitters(s, sel), std::invalid_argument);
  s.fraction[1] = iron;
  const std::vector<double> negative{0.0, 0.0, -0.1, 0.0, 0.0};
  s.fraction[0] = negative;
  try {
    selectVoxelEmitters(s, sel);
    FAIL() << "a negative fraction was accepted";
  } catch (const std::invalid_argument& err) {
    EXPECT_NE(std::string(err.what()).find("fraction[2]"), std::string::npos) << err.what();
  }
  s.fraction[0] = rock;
  s.voxelVolume = 0.0;
  EXPECT_THROW(selectVoxelEmitters(s, sel), std::invalid_argument);
}

// Howell B-3: a differential element to a parallel rectangle X c by Y c at distance c, one corner
// on the element's normal.
double cornerRectangle(double X, double Y) {
  const double a = std::sqrt(1.0 + X * X), b = std::sqrt(1.0 + Y * Y);
  return 1.0 / (2.0 * kPi) * (X / a * std::atan(Y / a) + Y / b * std::atan(X / b));
}
// ... to a square of side L centred on the normal at distance c.
double centredSquare(double L, double c) { return 4.0 * cornerRectangle(0.5 * L / c, 0.5 * L / c); }

TEST(VoxelEmitters, ThickHotSlabAgainstItsFacesViewFactor) {
  // A slab of 40 x 40 x 3 full voxels (a = 0.1 m: a 4 m square, 0.3 m thick) at 2000 K, its top
  // face at z = 0, seen from an element 1 m above the face's centre, facing it.
  const double a = 0.1, H = 1.0;
  const int n = 40, layers = 3;
  std::vector<double> x, y, z, T;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < layers; ++k) {
        x.push_back((i + 0.5 - 0.5 * n) * a);
        y.push_back((j + 0.5 - 0.5 * n) * a);
        z.push_back(-(k + 0.5) * a);
        T.push_back(2000.0);
      }
  VoxelEmitterSource s;
  s.x = x;
  s.y = y;
  s.z = z;
  s.temperature = T;
  s.voxelVolume = a * a * a;
  RadiationScene scene;
  scene.emitters = selectVoxelEmitters(s);
  ASSERT_EQ(scene.emitters.size(), static_cast<std::size_t>(n * n * layers));
  const ViewFactorSolver solver(scene);
  SamplingOptions o;
  o.rays = 1u << 20;
  const Estimate F = solver.fromPoint({0.0, 0.0, H}, {0.0, 0.0, -1.0}, o).toEmitters;

  // Bracket. Every sphere (radius r = 0.62 a) lies within the face square widened by r - a/2 =
  // 0.12 a per side and raised by 0.12 a: F <= that square's factor. Every ray that crosses the
  // plane of the top layer's centres inside their square (side L - a, 0.5 a below the face)
  // meets a top-layer sphere unless it passes one of the layer's pinholes: in that plane the
  // spheres' shadows along any direction are ellipses of area pi r^2 / cos(theta) about the
  // centres, so the uncovered share is largest at normal incidence, 1 - (4 quarter discs - 4 half
  // lenses) = 3.08% of a cell for r = 0.62 a; the rays' density varies by under 2% across a cell
  // here. So F >= (1 - 0.035) x that square's factor (deeper layers only block more).
  const double L = n * a, r = equalVolumeRadius(a * a * a);
  const double hi = centredSquare(L + 2.0 * (r - 0.5 * a), H - (r - 0.5 * a));
  const double lo = (1.0 - 0.035) * centredSquare(L - a, H + 0.5 * a);
  std::printf("hot slab F %.5f +- %.1e, bracket [%.5f, %.5f]; the face itself %.5f\n", F.value, F.standardError, lo,
              hi, centredSquare(L, H));
  EXPECT_GT(F.value, lo - 4.0 * F.standardError);
  EXPECT_LT(F.value, hi + 4.0 * F.standardError);
  EXPECT_LT(hi / lo - 1.0, 0.08);  // a bracket that can fail: 7% wide
}

}  // namespace
}  // namespace ejecta::radiation
