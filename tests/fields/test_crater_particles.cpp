// Crater measurement from particles (fields/measure_crater, crater_setup; issue 5): targets of
// particles with a known hole, measured through the whole chain (splat, lattice, ray marching),
// the crater setup worked out from impact scenes (a target cropped by the domain measured inside
// it), and an impact run that writes grids and puts the crater into summary.json.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>
#include <unistd.h>

#include "fields/crater_setup.hpp"
#include "fields/measure_crater.hpp"
#include "fields/run_outputs.hpp"
#include "fields/vdb_grids.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"
#include "tests/support/tiny_impact.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {
namespace {

constexpr double kPi = std::numbers::pi;

// A half-space target y <= 0 of particles at spacing dx with a hemispherical hole of radius a
// centred at the origin. RZ: rings (r, z) with r in (0, width); 3D: |x|, |z| < width.
ParticleSet holedHalfSpace(Geometry g, double width, double depth, double dx, double a) {
  ParticleSet p;
  const double rho = 2680.0;
  const bool rz = g == Geometry::Axisymmetric;
  const int nx = static_cast<int>(std::lround((rz ? width : 2 * width) / dx));
  const int ny = static_cast<int>(std::lround(depth / dx));
  const int nz = g == Geometry::Spatial ? nx : 1;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        const double x = (rz ? 0.0 : -width) + (i + 0.5) * dx;
        const double y = -(j + 0.5) * dx;
        const double z = g == Geometry::Spatial ? -width + (k + 0.5) * dx : 0.0;
        if (x * x + y * y + z * z < a * a) continue;
        double m = rho * std::pow(dx, spatialDimension(g));
        if (rz) m *= 2 * kPi * x;
        p.append({x, y, z}, {}, m, rho, 0.0, 1.2 * dx, 0);
      }
  p.numReal = p.size();
  return p;
}

CraterSetup planeSetup(bool planar, double searchLimit) {
  CraterSetup s;
  s.searchLimit = searchLimit;
  s.surface.kind = ReferenceSurface::Kind::Plane;
  s.surface.point = {0, 0, 0};
  s.surface.normal = {0, 1, 0};
  s.impactPoint = {0, 0, 0};
  s.planar = planar;
  s.targetDensity = 2680.0;
  s.targetMaterials = {0};
  s.targetNames = {"granite"};
  return s;
}

ParticleContext context(Geometry g) {
  ParticleContext c;
  c.geometry = g;
  c.materialNames = {"granite"};
  return c;
}

TEST(CraterFromParticles, HemisphericalHoleRZ) {
  const double a = 2.0, dx = 0.05;
  const ParticleSet p = holedHalfSpace(Geometry::Axisymmetric, 6.0, 5.0, dx, a);
  const CraterMetrics m = measureCrater(p, context(Geometry::Axisymmetric), planeSetup(false, 5.5));
  ASSERT_TRUE(m.found) << m.note;
  // The particles' own surface is the hole's edge give or take half a spacing (a lattice does
  // not fit a sphere), and the measuring resolution is 0.03 m: one spacing on lengths, and on
  // the volume twice the relative shell of half a spacing (3 * 0.025 / 2 = 3.8%): 5%.
  EXPECT_NEAR(m.depth, a, dx);
  EXPECT_NEAR(m.apparentDiameter, 2 * a, 2 * dx);
  const double volume = 2.0 / 3.0 * kPi * a * a * a;
  EXPECT_NEAR(m.volume / volume, 1.0, 0.05);
  EXPECT_NEAR(m.excavatedMass, 2680.0 * m.volume, 1e-6 * m.excavatedMass);
  EXPECT_NEAR(m.elongation, 1.0, 0.02);  // axisymmetric by construction
  EXPECT_LT(std::abs(m.rimHeight), dx);  // no rim
}

TEST(CraterFromParticles, HemisphericalHole3D) {
  const double a = 1.0, dx = 0.1;
  const ParticleSet p = holedHalfSpace(Geometry::Spatial, 2.0, 2.0, dx, a);
  const CraterMetrics m = measureCrater(p, context(Geometry::Spatial), planeSetup(false, 1.7));
  ASSERT_TRUE(m.found) << m.note;
  // As in RZ, with a coarser lattice (a = 10 spacings): one spacing on lengths, 10% on volume.
  EXPECT_NEAR(m.depth, a, dx);
  EXPECT_NEAR(m.apparentDiameter, 2 * a, 2 * dx);
  EXPECT_NEAR(m.volume / (2.0 / 3.0 * kPi * a * a * a), 1.0, 0.10);
  EXPECT_NEAR(m.elongation, 1.0, 0.1);
}

TEST(CraterFromParticles, HalfDiscHolePlanar) {
  const double a = 1.0, dx = 0.05;
  const ParticleSet p = holedHalfSpace(Geometry::Planar, 3.0, 2.5, dx, a);
  const CraterMetrics m = measureCrater(p, context(Geometry::Planar), planeSetup(true, 2.7));
  ASSERT_TRUE(m.found) << m.note;
  EXPECT_NEAR(m.depth, a, dx);
  EXPECT_NEAR(m.apparentDiameter, 2 * a, 2 * dx);
  // Area per metre of depth; the shell argument of the RZ case gives 2 * 0.025 / 1 = 5%.
  EXPECT_NEAR(m.volume / (kPi * a * a / 2), 1.0, 0.06);
}

std::string impactScene(const std::string& dimension, const std::string& extra = "") {
  test::TinyImpact o;
  o.dimension = dimension;
  o.extra = extra;
  return test::tinyImpactScene(o);
}

TEST(CraterSetupFromScene, ImpactScenesGiveSurfaceImpactPointAndTargets) {
  const Scene rz = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/impact_rz.toml");
  const auto s = craterSetupFromScene(rz);
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->surface.kind, ReferenceSurface::Kind::Sphere);
  EXPECT_DOUBLE_EQ(s->surface.radius, 35.0);
  EXPECT_NEAR(s->impactPoint[0], 0.0, 1e-12);
  EXPECT_NEAR(s->impactPoint[1], 35.0, 1e-9);
  EXPECT_EQ(s->targetNames, (std::vector<std::string>{"granite", "rubble"}));
  EXPECT_DOUBLE_EQ(s->targetDensity, 2680.0);
  EXPECT_FALSE(s->planar);

  const Scene oblique = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/impact_3d_oblique.toml");
  const auto o = craterSetupFromScene(oblique);
  ASSERT_TRUE(o.has_value());
  const Point& q = o->impactPoint;
  EXPECT_NEAR(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), 35.0, 1e-6);  // on the sphere
  EXPECT_NEAR(o->alongTrack[0], std::sqrt(0.5), 1e-4);
  EXPECT_NEAR(o->alongTrack[2], -std::sqrt(0.5), 1e-4);

  // A box target: the face the impactor's path meets, as a plane.
  const Scene box = parseScene(impactScene("2d"), "tiny.toml");
  const auto b = craterSetupFromScene(box);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->surface.kind, ReferenceSurface::Kind::Plane);
  EXPECT_DOUBLE_EQ(b->surface.normal[1], 1.0);
  EXPECT_NEAR(b->impactPoint[1], 0.0, 1e-12);
  EXPECT_TRUE(b->planar);

  // Not an impact: nothing moves.
  Scene still = box;
  for (BodySpec& body : still.bodies) body.velocity = {0, 0, 0};
  EXPECT_FALSE(craterSetupFromScene(still).has_value());
  // Switched off.
  EXPECT_FALSE(craterSetupFromScene(parseScene(impactScene("2d", "[crater]\nenabled = false\n"), "t")).has_value());
}

// scenes/impact_3d_oblique.toml's asteroid cropped to a box about the impact point, its faces
// `sides` (empty: open), the top `zMax`.
std::vector<std::string> cropOf(const std::string& sides, const std::string& zMax = "300 m",
                                const std::string& xMin = "-15 m", const std::string& yMin = "-16 m") {
  const std::string s = sides.empty() ? "" : ", boundary = \"" + sides + "\"";
  return {"domain.x={ min = \"" + xMin + "\", max = \"20 m\"" + s + " }",
          "domain.y={ min = \"" + yMin + "\", max = \"17 m\"" + s + " }",
          "domain.z={ min = \"19 m\", max = \"" + zMax + "\"" + s + " }"};
}

std::string sceneErrorOf(const std::string& path, const std::vector<std::string>& overrides) {
  try {
    craterSetupFromScene(loadScene(path, overrides));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CraterSetupFromScene, ACroppedTargetIsMeasuredInsideItsDomain) {
  const std::string path = std::string(EJECTA_SOURCE_DIR) + "/scenes/impact_3d_oblique.toml";
  const auto whole = craterSetupFromScene(loadScene(path));
  const auto cropped = craterSetupFromScene(loadScene(path, cropOf("")));
  ASSERT_TRUE(whole && cropped);
  EXPECT_EQ(whole->searchLimit, 0.0);  // the whole sphere: no limit
  // The nearest face is x = -15 m, 15 m from the impact point (about (0, 0, 35 m): the path
  // meets the sphere 1 cm from the pole), less 3 spacings of the 1 m crust: 12 m. The others:
  // y 16 and 17 m, z 16 m below (19 m), far above.
  EXPECT_NEAR(cropped->searchLimit, 12.0 + cropped->impactPoint[0], 1e-9);
  EXPECT_NEAR(cropped->searchLimit, 12.0, 0.02);
  // The crater is measured on the real particles alone: past a wall or a periodic side there is
  // no material either, so they limit the search as an open face does.
  EXPECT_EQ(craterSetupFromScene(loadScene(path, cropOf("wall")))->searchLimit, cropped->searchLimit);
  EXPECT_EQ(craterSetupFromScene(loadScene(path, cropOf("periodic")))->searchLimit, cropped->searchLimit);
  // A face above the surface cuts nothing the rays need: the top 1 m above the pole changes
  // nothing; nor does a face that misses the asteroid (y from -40 m: the sphere's edge is -35 m).
  EXPECT_EQ(craterSetupFromScene(loadScene(path, cropOf("", "36 m")))->searchLimit, cropped->searchLimit);
  EXPECT_NEAR(craterSetupFromScene(loadScene(path, cropOf("", "300 m", "-40 m", "-40 m")))->searchLimit,
              16.0 - 3.0, 1e-9);  // then the nearest is the bottom, 16 m below
  // An impact point too near a face, or outside the box, is refused by name.
  EXPECT_NE(sceneErrorOf(path, cropOf("", "300 m", "-3 m")).find(
                "crater: the impact point lies 3"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(path, cropOf("", "300 m", "-3 m")).find("inside the domain's lower x face"),
            std::string::npos);
  EXPECT_NE(sceneErrorOf(path, cropOf("", "300 m", "-15 m", "0.5 m")).find(
                "outside the domain, 0.5 m past its lower y face"),
            std::string::npos);

  // A bowl 4 m deep and 6 m in radius at the pole of the 35 m sphere, the material cut off at
  // the crop's faces. Measured with the cropped setup it is the whole body's crater, to
  // round-off (the rays inside the limit are the same rays); measured as if the body were whole,
  // the rays past the faces find no material and the crater runs to the search's end.
  const auto sphereWithBowl = [](const Point& p) {
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double q2 = p[0] * p[0] + p[1] * p[1];
    const bool inBowl = p[2] > 31.0 + 4.0 * q2 / 36.0;
    return r < 35.0 && !inBowl ? 1.0 : 0.0;
  };
  const auto croppedField = [&](const Point& p) {
    const bool inBox = p[0] > -15 && p[0] < 20 && p[1] > -16 && p[1] < 17 && p[2] > 19;
    return inBox ? sphereWithBowl(p) : 0.0;
  };
  const double resolution = 0.25;  // 120 resolutions: a 30 m search without the limit
  const CraterMetrics reference = analyseCrater(sphereWithBowl, craterOptions(*whole, resolution));
  const CraterMetrics inside = analyseCrater(croppedField, craterOptions(*cropped, resolution));
  ASSERT_TRUE(reference.found && inside.found) << reference.note << inside.note;
  EXPECT_DOUBLE_EQ(inside.depth, reference.depth);
  EXPECT_DOUBLE_EQ(inside.apparentDiameter, reference.apparentDiameter);
  EXPECT_NEAR(inside.volume, reference.volume, 1e-12 * reference.volume);
  // The bowl meets the sphere 5.645 m from the axis (31 + q^2/9 = sqrt(35^2 - q^2)); the
  // field is sharp, so the edge is found to within the bisection of a ray step.
  EXPECT_NEAR(reference.apparentDiameter, 2 * 35 * std::asin(5.645 / 35), 2 * resolution);
  const CraterMetrics blind = analyseCrater(croppedField, craterOptions(*whole, resolution));
  EXPECT_GT(blind.apparentDiameter, 2 * 15.0);
  EXPECT_NE(blind.note.find("found void at their start"), std::string::npos) << blind.note;
}

TEST(ImpactRunOutputs, GridsAndCraterAreWritten) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_impact_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const Scene scene = parseScene(
      impactScene("rz", "[fields]\ngrids = [\"density\", \"fractions\"]\nevery = 2\nvoxel = \"0.03 m\"\n"), "tiny.toml");
  RunOptions options;
  options.outDir = dir.string();
  options.threads = 2;
  options.configure = [](const Scene& s, RunOptions& o) { addFieldOutputs(o, s); };
  const RunOutcome r = runScene(scene, options);
  ASSERT_TRUE(r.ok) << r.error;
  // Snapshots 0, 1, 2 (the last): every = 2 writes 0 and 2, and the last always.
  EXPECT_TRUE(fs::exists(dir / "fields" / "fields_0000.vdb"));
  EXPECT_FALSE(fs::exists(dir / "fields" / "fields_0001.vdb"));
  ASSERT_TRUE(fs::exists(dir / "fields" / "fields_0002.vdb"));
  const std::vector<StoredGrid> grids = readGridFileInfo((dir / "fields" / "fields_0002.vdb").string());
  std::vector<std::string> names;
  for (const StoredGrid& g : grids) names.push_back(g.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"density", "fraction_aluminium", "fraction_granite",
                                              "surface", "surface_aluminium", "surface_granite"}));
  EXPECT_EQ(grids[0].scene, "tiny_impact");
  EXPECT_NEAR(grids[0].time, 60e-6, 1e-12);

  std::ifstream in(dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& x = j["extras"];
  ASSERT_TRUE(x.contains("crater_found"));
  ASSERT_TRUE(x["crater_found"].get<bool>()) << x.dump(2);
  // A 0.1 m aluminium ball at 3 km/s, 60 us in: the cavity is a few spacings deep (measured
  // 0.088 m) and wider than the ball (0.305 m), and far smaller than the target.
  EXPECT_GT(x["crater_depth_m"].get<double>(), 0.06);
  EXPECT_LT(x["crater_depth_m"].get<double>(), 0.3);
  EXPECT_GT(x["crater_apparent_diameter_m"].get<double>(), 0.15);
  EXPECT_LT(x["crater_apparent_diameter_m"].get<double>(), 1.0);
  EXPECT_TRUE(fs::exists(dir / "crater_profile.csv"));

  // The file measures the same crater as the particles, to a voxel or two (the grid's voxel is
  // the median h, twice the particle measurement's resolution).
  const GridFileCraterInput in2 = craterInputFromGridFile((dir / "fields" / "fields_0002.vdb").string());
  const CraterMetrics fromFile = analyseCrater(in2.field, craterOptions(in2.setup, in2.voxel));
  ASSERT_TRUE(fromFile.found) << fromFile.note;
  EXPECT_NEAR(fromFile.depth, x["crater_depth_m"].get<double>(), 2 * in2.voxel);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ejecta::fields
