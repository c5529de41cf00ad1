// The thermal chain (radiation/thermal_study.hpp) on synthetic emitters: the flux on a box's faces
// against analytic view factors, its growth along the approach, the wall and the sizing it
// drives, the output formats, and the study file's error messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "core/units.hpp"
#include "radiation/constants.hpp"
#include "radiation/thermal_study.hpp"
#include "radiation/wall_materials.hpp"

namespace ejecta::radiation {
namespace {

// A 0.4 m box hanging over the origin, side0 facing down (-y) at height `face` [m].
std::string studyText(double face, const std::string& approach, const std::string& rest = "",
                      long rays = 262144) {
  const double centre = face + 0.2;
  return "[study]\nname = \"synthetic\"\n"
         "[spacecraft]\nshape = \"box\"\nsize = [0.4, 0.4, 0.4]\nforward = [0.0, -1.0, 0.0]\nup = [1.0, 0.0, 0.0]\n"
         "[approach]\nstart = [0.0, " + std::to_string(centre) + ", 0.0]\n" + approach +
         "[sampling]\nrays = " + std::to_string(rays) + "\n" + rest;
}

const std::string kStatic = "velocity = [0.0, 0.0, 0.0]\nduration = \"1 ms\"\nsamples = 2\n";

// A disc of radius R in the plane y = 0 made of touching spheres (opaque lattice radius
// sqrt(2)/2 s for a plane of points), all at T with emissivity eps.
Emitters hotDisc(double R, double s, double T, double eps) {
  Emitters e;
  const double a = opaqueLatticeRadius(s) * std::sqrt(2.0 / 3.0);  // sqrt(3)/2 s * sqrt(2/3) = s / sqrt(2)
  const int n = static_cast<int>(std::ceil(R / s));
  for (int i = -n; i <= n; ++i)
    for (int k = -n; k <= n; ++k)
      if (std::hypot(i * s, k * s) <= R) e.add(i * s, 0.0, k * s, a, T, eps, "melt");
  return e;
}

// View factor from a differential element at height H, offset rho from the axis, facing a
// parallel coaxial disc of radius R (Howell B-13 / Modest D-12 generalised off axis):
// F = 1/2 (1 - (H^2 + rho^2 - R^2) / sqrt((H^2 + rho^2 + R^2)^2 - 4 R^2 rho^2)).
double elementToDisc(double H, double rho, double R) {
  const double a = H * H + rho * rho;
  return 0.5 * (1.0 - (a - R * R) / std::sqrt((a + R * R) * (a + R * R) - 4.0 * R * R * rho * rho));
}

// The face average of f(x, z) over the 0.4 m square face, midpoint rule with 200 x 200 points
// (the integrands are smooth; the rule's error is O(h^2) ~ 1e-7 relative here).
template <class F>
double faceAverage(F f) {
  const int n = 200;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) sum += f(-0.2 + 0.4 * (i + 0.5) / n, -0.2 + 0.4 * (k + 0.5) / n);
  return sum / (n * n);
}

const PatchThermal& patch(const ThermalResult& r, const std::string& name) {
  for (const PatchThermal& p : r.patches)
    if (p.patch == name) return p;
  throw std::runtime_error("no patch " + name);
}

TEST(ThermalStudy, FluxFromASingleSphereMatchesTheExactFaceAverage) {
  // One exact emitter sphere (radius 0.3 m, 3000 K, eps 0.45) centred 1.5 m below the face. An
  // element at offset rho sees it at d = sqrt(D^2 + rho^2), tilted by cos = D / d, wholly above
  // its horizon: F = cos (a/d)^2 (Modest D-18), averaged over the face.
  const ThermalStudy s = parseThermalStudy(studyText(1.5, kStatic, "", 1 << 20), "synthetic.toml", ".");
  Emitters e;
  e.add(0.0, 0.0, 0.0, 0.3, 3000.0, 0.45, "melt");
  const ThermalResult r = runThermalStudy(s, e);
  const double F = faceAverage([](double x, double z) {
    const double d2 = 1.5 * 1.5 + x * x + z * z;
    return 0.09 * 1.5 / (d2 * std::sqrt(d2));
  });
  const double exact = 0.45 * kStefanBoltzmann * std::pow(3000.0, 4) * F;
  const PatchThermal& side0 = patch(r, "side0");
  // The scene is exact (an Embree sphere, a planar face): only the Monte Carlo error remains;
  // 4 standard errors (t with 15 degrees of freedom: p ~ 1e-3).
  EXPECT_NEAR(side0.flux[0].value, exact, 4.0 * side0.flux[0].standardError) << "exact " << exact;
  EXPECT_LT(side0.flux[0].standardError, 0.005 * exact);
  std::printf("sphere: exact %.6g, ray-cast %.6g +- %.3g W/m^2\n", exact, side0.flux[0].value, side0.flux[0].standardError);
  EXPECT_EQ(patch(r, "aft").peakFlux, 0.0);
}

TEST(ThermalStudy, HotDiscUnderABoxFacingSideMatchesTheDiscViewFactor) {
  // Disc R = 1 m at 3000 K (eps 0.45) of spheres 0.02 m apart; side0 1 m above it.
  const double R = 1.0, s = 0.02, a = s / std::sqrt(2.0), H = 1.0;
  const ThermalStudy study = parseThermalStudy(studyText(H, kStatic), "synthetic.toml", ".");
  const Emitters disc = hotDisc(R, s, 3000.0, 0.45);
  const ThermalResult r = runThermalStudy(study, disc);
  const double exitance = 0.45 * kStefanBoltzmann * std::pow(3000.0, 4);
  // The sphere layer is not a flat disc: its top is between y = 0 and y = a and its rim between
  // R - s/2 and R + a. The analytic flux of the flat discs at those extremes brackets the
  // lattice's (the factor grows with the radius and as the disc comes closer).
  const double lo = exitance * faceAverage([&](double x, double z) { return elementToDisc(H, std::hypot(x, z), R - s / 2); });
  const double hi = exitance * faceAverage([&](double x, double z) { return elementToDisc(H - a, std::hypot(x, z), R + a); });
  const PatchThermal& side0 = patch(r, "side0");
  const double se = side0.flux[0].standardError;
  EXPECT_GT(side0.flux[0].value, lo - 3.0 * se) << "bracket [" << lo << ", " << hi << "]";
  EXPECT_LT(side0.flux[0].value, hi + 3.0 * se) << "bracket [" << lo << ", " << hi << "]";
  EXPECT_LT(hi / lo - 1.0, 0.05);
  std::printf("disc: bracket [%.6g, %.6g], ray-cast %.6g +- %.3g W/m^2\n", lo, hi, side0.flux[0].value, se);  // the bracket is a real check: under 5 % wide
  // The side faces see the disc at grazing angles: less, but not nothing; the back face nothing.
  for (const char* side : {"side1", "side2", "side3", "side4"}) {
    EXPECT_GT(patch(r, side).peakFlux, 0.0) << side;
    EXPECT_LT(patch(r, side).peakFlux, 0.25 * side0.peakFlux) << side;
  }
  EXPECT_EQ(patch(r, "aft").peakFlux, 0.0);
  EXPECT_EQ(patch(r, "aft").flux[0].standardError, 0.0);
  // The seed's sum counts every sphere in front of the face, whatever its size: far above.
  EXPECT_GT(side0.peakSeedFlux, 10.0 * side0.peakFlux);
  // Eq. 4.8 with no wall: a black face.
  EXPECT_NEAR(side0.steadyTemperature, std::pow(side0.peakFlux / kStefanBoltzmann, 0.25), 1e-9 * side0.steadyTemperature);
}

TEST(ThermalStudy, FluxGrowsAsTheCraftApproaches) {
  // From 4 m to 1 m above a 1 m disc: three samples at 3 km/s over 1 ms.
  const std::string approach = "speed = \"3 km/s\"\ntarget = [0.0, 0.0, 0.0]\nduration = \"1 ms\"\nsamples = 3\n";
  ThermalStudy study = parseThermalStudy(studyText(4.0, approach, "", 65536), "approach.toml", ".");
  const ThermalResult r = runThermalStudy(study, hotDisc(1.0, 0.05, 3000.0, 0.45));
  ASSERT_EQ(r.times.size(), 3u);
  EXPECT_DOUBLE_EQ(r.times[2], 1e-3);
  const PatchThermal& side0 = patch(r, "side0");
  for (std::size_t i = 1; i < 3; ++i) {
    const double se = std::hypot(side0.flux[i].standardError, side0.flux[i - 1].standardError);
    EXPECT_GT(side0.flux[i].value - side0.flux[i - 1].value, 5.0 * se) << "sample " << i;
  }
  // The flux at 1 m is about that of the flat disc (Modest D-12 on the axis: 0.5; the face
  // average is a little lower): within 10 %.
  const double q1 = 0.45 * kStefanBoltzmann * std::pow(3000.0, 4) * 0.5;
  EXPECT_NEAR(side0.flux[2].value / q1, 1.0, 0.1);
  EXPECT_DOUBLE_EQ(side0.peakTime, 1e-3);
}

ThermalResult sizedAt(double temperature) {
  // A static craft 1 m over the disc for 50 ms; 0.2 mm aluminium structure, limit 2 K above the
  // start: the bare structure fails, and thicker coatings hold more of the heat.
  const std::string rest =
      "[[walls]]\npatches = [\"side0\"]\nlayers = [{ material = \"aluminium\", thickness = \"0.2 mm\", cells = 10 }]\n"
      "[wall]\ninitial_temperature = 293.15\ntime_step = \"50 us\"\n"
      "[limit]\nkind = \"temperature\"\nvalue = 295.15\n"
      "[sizing]\ncoatings = [\"aluminium\", \"tungsten\"]\npatches = [\"side0\"]\n";
  const std::string approach = "velocity = [0.0, 0.0, 0.0]\nduration = \"50 ms\"\nsamples = 2\n";
  const ThermalStudy study = parseThermalStudy(studyText(1.0, approach, rest, 65536), "sizing.toml", ".");
  return runThermalStudy(study, hotDisc(1.0, 0.05, temperature, 0.45));
}

TEST(ThermalStudy, WallAndSizingFollowTheFlux) {
  const ThermalResult cool = sizedAt(3000.0), hot = sizedAt(3300.0);
  const PatchThermal& c = patch(cool, "side0");
  const PatchThermal& h = patch(hot, "side0");
  ASSERT_TRUE(c.wall.has_value());
  EXPECT_FALSE(patch(cool, "side1").wall.has_value());
  // Bare 0.2 mm aluminium: the absorbed energy 0.09 q t over rho c_p L, insulated behind (lumped:
  // aluminium's diffusion time L^2/alpha = 0.4 ms << 50 ms; re-radiation at eps 0.06 and ~300 K
  // is 0.03 % of the absorbed flux).
  const WallMaterial& al = wallMaterial("aluminium");
  const double rise = 0.09 * c.peakFlux * 0.05 / (al.density * al.specificHeat * 0.2e-3);
  EXPECT_NEAR(c.layerPeak[0] - 293.15, rise, 0.01 * rise);
  EXPECT_FALSE(c.structureWithinLimit);
  ASSERT_EQ(c.sizing.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_TRUE(c.sizing[k].feasible && h.sizing[k].feasible) << c.sizing[k].material;
    EXPECT_GT(c.sizing[k].thickness, 0.0);
    EXPECT_GT(h.sizing[k].thickness, c.sizing[k].thickness) << c.sizing[k].material;  // more flux, thicker
    const WallMaterial& m = wallMaterial(c.sizing[k].material);
    EXPECT_NEAR(c.sizing[k].addedMass, m.density * c.sizing[k].thickness * c.area, 1e-12 * c.sizing[k].addedMass);
    EXPECT_LT(c.sizing[k].structurePeak, 295.15);
  }
  // Thicker aluminium: the lumped estimate total thickness = 0.09 q t / (rho c_p 2 K), less 0.2 mm.
  const double lumped = 0.09 * c.peakFlux * 0.05 / (al.density * al.specificHeat * 2.0) - 0.2e-3;
  EXPECT_NEAR(c.sizing[0].thickness / lumped, 1.0, 0.05);
  std::printf("sizing: bare rise %.4g K (lumped %.4g); Al %.4g mm (lumped %.4g), W %.4g mm; at 3300 K: %.4g, %.4g mm\n",
              c.layerPeak[0] - 293.15, rise, c.sizing[0].thickness * 1e3, lumped * 1e3, c.sizing[1].thickness * 1e3,
              h.sizing[0].thickness * 1e3, h.sizing[1].thickness * 1e3);
  EXPECT_NEAR(cool.totalAddedMass.at("tungsten"), c.sizing[1].addedMass, 1e-12);

  // Outputs: one CSV row per sample with flux and error per patch; the JSON summary parses.
  const std::string csv = formatThermalFluxCsv(cool);
  EXPECT_EQ(csv.rfind("time_s,side0_W_m2,side0_se_W_m2,", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
  const nlohmann::json j = nlohmann::json::parse(formatThermalJson(cool, "  \"extra\": 1"));
  EXPECT_EQ(j["extra"], 1);
  EXPECT_EQ(j["patches"].size(), 6u);
  EXPECT_NEAR(j["patches"][0]["peak_flux_W_m2"].get<double>(), cool.patches[0].peakFlux, 1e-9 * cool.patches[0].peakFlux);
  EXPECT_EQ(j["patches"][0]["sizing"].size(), 2u);
  EXPECT_TRUE(j["patches"][0].contains("seed_baseline"));
  const std::string sizing = formatThermalSizingCsv(cool);
  EXPECT_EQ(std::count(sizing.begin(), sizing.end(), '\n'), 3);
}

// A study reads its quantities with core's parser, the scenes' one: units only a scene took
// before (compound, other prefixes, the Greek mu) give the value a scene gives.
TEST(ThermalStudy, AcceptsEveryUnitASceneAccepts) {
  const std::string approach = "speed = \"3.6e7 m/ks\"\ntarget = [\"0 m\", \"0.5 mm\", 0.0]\n"
                               "duration = \"1500 \xCE\xBCs\"\nsamples = 2\n";
  const std::string rest =
      "[emitters]\nmin_temperature = \"1.5e3 K\"\n"
      "[[walls]]\nlayers = [{ material = \"aluminium\", thickness = \"3e6 nm\" }]\n"
      "[wall]\ntime_step = \"5e3 ns\"\n"
      "[sizing]\ncoatings = [\"tungsten\"]\nmax_thickness = \"2e-6 km\"\n"
      "[baseline]\nlength = \"4e11 pm\"\n";
  const ThermalStudy s = parseThermalStudy(studyText(1.0, approach, rest), "units.toml", ".");
  EXPECT_DOUBLE_EQ(vec3::norm(s.approach.velocity), parseQuantity("3.6e7 m/ks", Dimension::Velocity));
  EXPECT_DOUBLE_EQ(vec3::norm(s.approach.velocity), 3.6e4);
  EXPECT_DOUBLE_EQ(s.approach.target[1], 5e-4);  // vectors take units too
  EXPECT_EQ(s.approach.duration, parseQuantity("1500 \xCE\xBCs", Dimension::Time));
  EXPECT_DOUBLE_EQ(s.approach.duration, 1.5e-3);
  EXPECT_DOUBLE_EQ(s.emitters.minTemperature, 1500.0);
  ASSERT_EQ(s.walls.size(), 1u);
  EXPECT_EQ(s.walls[0].layers[0].thickness, parseQuantity("3e6 nm", Dimension::Length));
  EXPECT_DOUBLE_EQ(s.walls[0].layers[0].thickness, 3e-3);
  EXPECT_EQ(s.timeStep, parseQuantity("5e3 ns", Dimension::Time));
  EXPECT_DOUBLE_EQ(s.timeStep, 5e-6);
  EXPECT_EQ(s.sizing.maxThickness, parseQuantity("2e-6 km", Dimension::Length));
  EXPECT_DOUBLE_EQ(s.sizing.maxThickness, 2e-3);
  EXPECT_EQ(s.baseline.receiverSide, parseQuantity("4e11 pm", Dimension::Length));
  EXPECT_DOUBLE_EQ(s.baseline.receiverSide, 0.4);
}

void expectError(const std::string& text, const std::string& expected) {
  try {
    const ThermalStudy s = parseThermalStudy(text, "bad.toml", ".");
    runThermalStudy(s, Emitters{});
    ADD_FAILURE() << "no error, expected: " << expected;
  } catch (const ThermalStudyError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

TEST(ThermalStudy, BadStudyFilesNameFileLineAndKey) {
  const std::string ok = "[approach]\nstart = [0.0, 5.0, 0.0]\nspeed = \"1 km/s\"\nduration = \"1 ms\"\n";
  expectError("[spacecraft]\nshape = \"box\"\n", "bad.toml:1: key 'approach': required");
  expectError(ok + "colour = 3\n", "bad.toml:5: key 'approach.colour': unknown key");
  expectError("[approach]\nstart = [0.0, 5.0, 0.0]\nspeed = \"1 km\"\nduration = \"1 ms\"\n",
              "bad.toml:3: key 'approach.speed': expected a velocity (m/s), got a length (m) in '1 km'");
  expectError("[approach]\nstart = [0.0, 5.0, 0.0]\nspeed = \"1 furlong/s\"\nduration = \"1 ms\"\n",
              "bad.toml:3: key 'approach.speed': unknown unit 'furlong'");
  expectError("[approach]\nstart = [0.0, 5.0, 0.0]\nspeed = \"1 km/s\"\nduration = -1.0\n",
              "bad.toml:4: key 'approach.duration': must be > 0");
  expectError(ok + "[[walls]]\nlayers = [{ material = \"unobtainium\", thickness = \"1 mm\" }]\n",
              "bad.toml:6: key 'walls[0].layers[0].material'");
  expectError(ok + "[[walls]]\npatch = \"side9\"\nlayers = [{ material = \"aluminium\", thickness = \"1 mm\" }]\n",
              "no patch 'side9'");
  expectError(ok + "[emitters]\nemissivity = { granite = 1.5 }\n", "bad.toml:6: key 'emitters.emissivity.granite': must be in (0, 1]");
  expectError(ok + "[limit]\nkind = \"hot\"\n", "bad.toml:6: key 'limit.kind': unknown value 'hot'");
  expectError(ok + "[sizing]\ncoatings = [\"tungsten\"]\n", "bad.toml:6: key 'sizing.coatings': sizing needs a structure");
  expectError(ok + "[spacecraft]\nshape = \"box\"\nradius = 1.0\n", "bad.toml:7: key 'spacecraft.radius': not used by shape 'box'");
  expectError("[approach\n", "bad.toml:1:");
}

}  // namespace
}  // namespace ejecta::radiation
