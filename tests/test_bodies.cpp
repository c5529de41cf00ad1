// Particle generation: lattice counts and spacings, total mass against the shape's volume (exact
// where the lattice tiles the shape, within a stated discreteness tolerance otherwise), RZ ring
// masses, overlap rules, initial state, and energy deposits that add exactly E.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "sim/bodies.hpp"

namespace ejecta {
namespace {

constexpr double kPi = std::numbers::pi;

// A scene with one gas (gamma 1.4) and the given domain / bodies / deposits sections.
std::string sceneText(const std::string& dimension, const std::string& rest) {
  return "[scene]\nname = \"t\"\ndimension = \"" + dimension +
         "\"\n[time]\nt_end = 1\n[[materials]]\nname = \"gas\"\ngamma = 1.4\n" + rest;
}

ParticleSet build(const Scene& s) { return buildParticles(s, MaterialTable::fromScene(s)); }
ParticleSet build(const std::string& dimension, const std::string& rest) {
  return build(parseScene(sceneText(dimension, rest), "t.toml"));
}

double totalMass(const ParticleSet& p) {
  double m = 0.0;
  for (double x : p.mass) m += x;
  return m;
}

double totalInternalEnergy(const ParticleSet& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) e += p.mass[i] * p.u[i];
  return e;
}

std::string body(const std::string& name, const std::string& shapeKeys, double spacing,
                 double density, const std::string& extra = "pressure = 1.0\n") {
  return "[[bodies]]\nname = \"" + name + "\"\nmaterial = \"gas\"\n" + shapeKeys +
         "\nspacing = " + std::to_string(spacing) + "\ndensity = " + std::to_string(density) +
         "\n" + extra;
}

double minPairDistance(const ParticleSet& p, int dim) {
  double best = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) r2 += std::pow(p.x[d][i] - p.x[d][j], 2);
      best = std::min(best, r2);
    }
  return std::sqrt(best);
}

TEST(Bodies, LineBoxIsTiledExactly) {
  const ParticleSet p =
      build("1d", body("rod", "shape = \"box\"\nmin = [0]\nmax = [1]", 0.01, 2.0));
  ASSERT_EQ(p.size(), 100u);
  EXPECT_EQ(p.numReal, 100u);
  EXPECT_NEAR(p.x[0][0], 0.005, 1e-15);  // min + s/2
  EXPECT_NEAR(p.x[0][99], 0.995, 1e-12);
  EXPECT_NEAR(totalMass(p), 2.0, 1e-12);  // kg per m^2 of cross-section
  EXPECT_NEAR(p.h[0], 1.2 * 0.01, 1e-15);
  EXPECT_NEAR(p.u[0], 1.0 / (0.4 * 2.0), 1e-15);  // from P via the ideal gas
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p.id[i], static_cast<std::int64_t>(i));
}

TEST(Bodies, PlanarCubicBoxMassIsDensityTimesArea) {
  const ParticleSet p =
      build("2d", body("slab", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 2]", 0.05, 2.0,
                       "internal_energy = 3.0\nvelocity = [\"1 km/s\", -2]\n"));
  EXPECT_EQ(p.size(), 20u * 40u);
  EXPECT_NEAR(totalMass(p), 2.0 * 2.0, 1e-12);  // per metre of depth
  EXPECT_DOUBLE_EQ(p.u[5], 3.0);
  EXPECT_DOUBLE_EQ(p.v[0][5], 1000.0);
  EXPECT_DOUBLE_EQ(p.v[1][5], -2.0);
  EXPECT_DOUBLE_EQ(p.rho[5], 2.0);
}

TEST(Bodies, PlanarHexagonalLattice) {
  const double s = 0.02, rho = 2.0;
  const ParticleSet p = build(
      "2d",
      body("slab", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]\nlattice = \"hexagonal\"", s, rho));
  const double cell = s * s * std::sqrt(3.0) / 2.0;
  EXPECT_NEAR(latticeCellVolume(LatticeKind::Hexagonal, 2, s), cell, 1e-18);
  EXPECT_DOUBLE_EQ(p.mass[0], rho * cell);
  EXPECT_NEAR(p.h[0], 1.2 * std::sqrt(cell), 1e-15);
  EXPECT_NEAR(minPairDistance(p, 2), s, 1e-12);  // nearest neighbours at the spacing
  // Rows do not tile the box exactly: allow one lattice layer along half the perimeter.
  const double tolerance = rho * s * 4.0 / 2.0;
  EXPECT_NEAR(totalMass(p), rho * 1.0, tolerance);
}

TEST(Bodies, SphereIn3dCubicAndClosePacked) {
  const double R = 1.0, s = 0.05, rho = 3.0;
  const double exact = rho * 4.0 / 3.0 * kPi * R * R * R;
  for (const char* lattice : {"cubic", "hexagonal"}) {
    SCOPED_TRACE(lattice);
    const ParticleSet p = build(
        "3d", body("ball",
                   std::string("shape = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nlattice = \"") +
                       lattice + "\"",
                   s, rho));
    // Lattice cells whose centres lie inside a sphere of 20 spacings: the surface's
    // discreteness averages out to well under 1 % of the volume.
    EXPECT_NEAR(totalMass(p), exact, 0.01 * exact);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double r = std::hypot(p.x[0][i], p.x[1][i], p.x[2][i]);
      ASSERT_LE(r, R);
    }
  }
}

TEST(Bodies, ClosePackedNearestNeighbourIsTheSpacing) {
  const double s = 0.1;
  const ParticleSet p =
      build("3d", body("cube",
                       "shape = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]\nlattice = \"hexagonal\"",
                       s, 1.0));
  EXPECT_NEAR(minPairDistance(p, 3), s, 1e-12);
  EXPECT_NEAR(p.mass[0], s * s * s / std::sqrt(2.0), 1e-15);
  // sqrt(2)/s^3 points per unit volume, within a surface layer.
  EXPECT_NEAR(static_cast<double>(p.size()), std::sqrt(2.0) / (s * s * s), 0.15 * 1414.0);
}

TEST(Bodies, RzCylinderRingMassIsExact) {
  // The rings of a box r in [0, R], z in [0, H] whose width divides R: sum 2 pi r_i s^2 rho is
  // the midpoint rule for an integrand linear in r, hence exact.
  const double R = 1.0, H = 2.0, s = 0.05, rho = 1.5;
  const ParticleSet p =
      build("rz", "[domain]\nx = { min = 0, max = 1, boundary = \"wall\" }\n" +
                      body("can", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 2]", s, rho));
  EXPECT_EQ(p.size(), 20u * 40u);
  EXPECT_NEAR(totalMass(p), rho * kPi * R * R * H, 1e-12 * rho * kPi * R * R * H);
  double rmin = INFINITY;
  for (double r : p.x[0]) rmin = std::min(rmin, r);
  EXPECT_NEAR(rmin, s / 2.0, 1e-15);  // only r > 0 exists; the first column at s/2
  EXPECT_NEAR(p.mass[0], rho * s * s * 2.0 * kPi * p.x[0][0], 1e-15);
  EXPECT_NEAR(p.h[0], 1.2 * s, 1e-15);  // RZ: h from the cell area (d = 2)
}

TEST(Bodies, RzSphereAndHexagonalCylinder) {
  const double R = 1.0, s = 0.02, rho = 1.0;
  const ParticleSet ball =
      build("rz", body("ball", "shape = \"sphere\"\ncenter = [0, 0]\nradius = 1", s, rho));
  const double sphere = rho * 4.0 / 3.0 * kPi * R * R * R;
  EXPECT_NEAR(totalMass(ball), sphere, 0.005 * sphere);
  for (double r : ball.x[0]) ASSERT_GT(r, 0.0);

  const ParticleSet can = build(
      "rz",
      body("can", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]\nlattice = \"hexagonal\"", s, rho));
  // Hexagonal rows do not tile the box: one lattice layer around the (r, z) outline, weighted
  // by the largest ring circumference.
  const double cylinder = rho * kPi * R * R;
  EXPECT_NEAR(totalMass(can), cylinder, rho * s * 4.0 / 2.0 * 2.0 * kPi * R);
}

TEST(Bodies, EarlierBodiesWinAndMaterialsFollowBodies) {
  const std::string toml = sceneText(
      "2d", "[[materials]]\nname = \"dense\"\ngamma = 3\n" +
                body("core", "shape = \"sphere\"\ncenter = [0, 0]\nradius = 0.3", 0.05, 4.0) +
                "[[bodies]]\nname = \"rest\"\nmaterial = \"dense\"\nshape = \"box\"\n"
                "min = [-1, -1]\nmax = [1, 1]\nspacing = 0.05\ndensity = 1\n"
                "pressure = 1\n");
  const Scene scene = parseScene(toml, "t.toml");
  const ParticleSet p = build(scene);
  // Both lattices fall on the same grid (the box's width is a whole number of spacings), so
  // the box's points inside the core are replaced one for one.
  EXPECT_EQ(p.size(), 40u * 40u);
  EXPECT_NEAR(minPairDistance(p, 2), 0.05, 1e-12);
  std::size_t core = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const bool inside = std::hypot(p.x[0][i], p.x[1][i]) <= 0.3;
    EXPECT_EQ(p.material[i], inside ? 0 : 1);
    EXPECT_DOUBLE_EQ(p.rho[i], inside ? 4.0 : 1.0);
    core += inside ? 1 : 0;
  }
  EXPECT_GT(core, 100u);
  EXPECT_NEAR(p.u[p.size() - 1], 1.0 / (2.0 * 1.0), 1e-15);  // gamma 3 material
}

TEST(Bodies, HalfSpaceAndShell) {
  const ParticleSet ground = build(
      "2d",
      "[domain]\nx = { min = 0, max = 1 }\ny = { min = 0, max = 1 }\n" +
          body("ground", "shape = \"half_space\"\npoint = [0, 0.5]\nnormal = [0, 1]", 0.05, 2.0));
  EXPECT_EQ(ground.size(), 20u * 10u);
  EXPECT_NEAR(totalMass(ground), 2.0 * 0.5, 1e-12);

  const ParticleSet ring = build(
      "2d", body("ring", "shape = \"shell\"\ncenter = [0, 0]\ninner_radius = 0.5\nouter_radius = 1",
                 0.01, 1.0));
  const double area = kPi * (1.0 - 0.25);
  EXPECT_NEAR(totalMass(ring), area, 0.005 * area);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double r = std::hypot(ring.x[0][i], ring.x[1][i]);
    ASSERT_GE(r, 0.5);
    ASSERT_LE(r, 1.0);
  }
}

TEST(Bodies, DomainClipsBodies) {
  const ParticleSet p =
      build("2d", "[domain]\nx = { min = 0, max = 0.5, boundary = \"wall\" }\n" +
                      body("slab", "shape = \"box\"\nmin = [-1, 0]\nmax = [1, 1]", 0.05, 1.0));
  EXPECT_EQ(p.size(), 10u * 20u);
  for (double x : p.x[0]) {
    ASSERT_GE(x, 0.0);
    ASSERT_LE(x, 0.5);
  }
}

TEST(Bodies, TopHatDepositAddsExactlyE) {
  const double E = 1234.5;
  for (const char* dim : {"1d", "2d", "rz", "3d"}) {
    SCOPED_TRACE(dim);
    const std::string d = dim;
    const std::string v = d == "1d" ? "[0]" : d == "3d" ? "[0, 0, 0]" : "[0, 0]";
    const std::string lo = d == "1d"   ? "[-1]"
                           : d == "3d" ? "[-1, -1, -1]"
                           : d == "rz" ? "[0, -1]"
                                       : "[-1, -1]";
    const std::string hi = d == "1d" ? "[1]" : d == "3d" ? "[1, 1, 1]" : "[1, 1]";
    const std::string shape = "shape = \"box\"\nmin = " + lo + "\nmax = " + hi;
    const std::string bodies = body("gas", shape, d == "3d" ? 0.1 : 0.05, 1.0);
    const ParticleSet before = build(dim, bodies);
    const ParticleSet after =
        build(dim, bodies + "[[energy_deposits]]\nname = \"blast\"\nenergy = " + std::to_string(E) +
                       "\ncenter = " + v + "\nradius = 0.3\n");
    EXPECT_NEAR(totalInternalEnergy(after) - totalInternalEnergy(before), E, 1e-10 * E);
    // Uniform in the region, zero outside.
    double du = -1.0;
    for (std::size_t i = 0; i < after.size(); ++i) {
      const double r2 = after.x[0][i] * after.x[0][i] + after.x[1][i] * after.x[1][i] +
                        after.x[2][i] * after.x[2][i];
      const double added = after.u[i] - before.u[i];
      if (r2 > 0.3 * 0.3) {
        ASSERT_EQ(added, 0.0);
        continue;
      }
      if (du < 0.0) du = added;
      ASSERT_NEAR(added, du, 1e-9 * du);
    }
    EXPECT_GT(du, 0.0);
  }
}

TEST(Bodies, GaussianDepositAddsExactlyE) {
  const std::string bodies =
      body("gas", "shape = \"box\"\nmin = [-1, -1, -1]\nmax = [1, 1, 1]", 0.1, 1.0);
  const ParticleSet before = build("3d", bodies);
  const ParticleSet after =
      build("3d", bodies +
                      "[[energy_deposits]]\nname = \"g\"\nenergy = \"1 kt\"\ncenter = [0.2, 0, 0]\n"
                      "profile = \"gaussian\"\nwidth = 0.15\n");
  const double E = 4.184e12;
  EXPECT_NEAR(totalInternalEnergy(after) - totalInternalEnergy(before), E, 1e-10 * E);
}

std::string errorOf(const std::string& dimension, const std::string& rest) {
  try {
    build(dimension, rest);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Bodies, EmptyBodiesAndDepositsAreErrors) {
  // A disc of radius 0.3 s centred between four lattice points holds none of them.
  std::string msg =
      errorOf("2d", body("tiny", "shape = \"sphere\"\ncenter = [0, 0]\nradius = 0.003", 0.01, 1.0));
  EXPECT_NE(msg.find("t.toml:9: key 'bodies[0]': body 'tiny': produces no particles"),
            std::string::npos)
      << msg;

  msg = errorOf(
      "2d", body("all", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]", 0.1, 1.0) +
                body("hidden", "shape = \"box\"\nmin = [0.2, 0.2]\nmax = [0.4, 0.4]", 0.1, 1.0));
  EXPECT_NE(msg.find("body 'hidden': produces no particles"), std::string::npos) << msg;

  msg = errorOf("2d", body("gas", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]", 0.1, 1.0) +
                          "[[energy_deposits]]\nname = \"spark\"\nenergy = 1\n"
                          "center = [0.5, 0.5]\nradius = 0.01\n");
  EXPECT_NE(msg.find("key 'energy_deposits[0]': deposit 'spark' covers no particles"),
            std::string::npos)
      << msg;
}

TEST(Bodies, AbsurdSpacingIsAnErrorNotACrash) {
  const std::string msg =
      errorOf("3d", body("cube", "shape = \"box\"\nmin = [0, 0, 0]\nmax = [1, 1, 1]", 1e-6, 1.0));
  EXPECT_NE(msg.find("body 'cube': the spacing would give about"), std::string::npos) << msg;
}

TEST(Bodies, NoParticleOnAWall) {
  // Odd hexagonal rows are shifted by s/2 and would put a point exactly on x = 1.
  const ParticleSet p = build(
      "2d", "[domain]\nx = { min = 0, max = 1, boundary = \"wall\" }\n" +
                body("slab", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]\nlattice = \"hexagonal\"",
                     0.02, 1.0));
  for (double x : p.x[0]) {
    ASSERT_GT(x, 0.0);
    ASSERT_LT(x, 1.0);
  }
}

TEST(Bodies, VerificationScenesBuild) {
  const std::filesystem::path dir =
      std::filesystem::path(EJECTA_SOURCE_DIR) / "scenes/verification";
  for (const char* name : {"sod_1d.toml", "sod_2d.toml", "sedov_2d.toml", "sedov_rz.toml"}) {
    SCOPED_TRACE(name);
    const Scene s = loadScene((dir / name).string());
    const ParticleSet p = build(s);
    EXPECT_GT(p.size(), 100u);
    const std::string n = name;
    if (n.rfind("sod", 0) == 0) {  // equal masses across the interface
      const auto [lo, hi] = std::minmax_element(p.mass.begin(), p.mass.end());
      EXPECT_NEAR(*hi / *lo, 1.0, 1e-9);
    }
    if (n == "sod_1d.toml") {
      EXPECT_NEAR(totalMass(p), 0.5 + 0.125 * 0.5, 1e-12);
    }
    if (n == "sedov_rz.toml") {
      const double ambient = 0.1 / 0.4 * totalMass(p);
      EXPECT_NEAR(totalInternalEnergy(p) - ambient, 1e5, 1e-6 * 1e5);
    }
  }
}

}  // namespace
}  // namespace ejecta
