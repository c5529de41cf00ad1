// Particle generation: lattice counts and spacings, total mass against the shape's volume (exact
// where the lattice tiles the shape, within a stated discreteness tolerance otherwise), RZ ring
// masses, overlap rules, initial state, and energy deposits that add exactly E. Void bodies (a
// crater's bowl, a cavity): what they carve, the bowl's exact size, their errors, and the study
// scenes built on them (docs/asteroid_studies.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "fields/crater.hpp"
#include "fields/grid_set.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/bodies.hpp"

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

// ---------------------------------------------------------------------------------------------
// Void bodies (void = true): space claimed without particles, e.g. the crater an impactor left.

std::string voidBody(const std::string& name, const std::string& shapeKeys) {
  return "[[bodies]]\nname = \"" + name + "\"\nvoid = true\n" + shapeKeys + "\n";
}

bool samePosition(const ParticleSet& a, std::size_t i, const ParticleSet& b, std::size_t j) {
  return a.x[0][i] == b.x[0][j] && a.x[1][i] == b.x[1][j] && a.x[2][i] == b.x[2][j];
}

TEST(Bodies, VoidCarvesTheBodiesAfterItAndNothingElse) {
  const std::string hole = voidBody("hole", "shape = \"sphere\"\ncenter = [0.5, 1.0]\nradius = 0.3");
  const std::string plug =
      body("plug", "shape = \"sphere\"\ncenter = [0.5, 0.85]\nradius = 0.1", 0.02, 3.0);
  const std::string slab = body("slab", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]", 0.02, 1.0);
  const ParticleSet full = build("2d", plug + slab);
  const Scene carvedScene = parseScene(sceneText("2d", plug + hole + slab), "t.toml");
  ASSERT_EQ(carvedScene.bodies.size(), 2u);
  ASSERT_EQ(carvedScene.voids.size(), 1u);
  EXPECT_EQ(carvedScene.voids[0].firstCarved, 1u);  // listed after the plug, before the slab
  const ParticleSet carved = build(carvedScene);

  // The carved set is the full set less the slab's points in the hole, in the same order and
  // with the same state; the plug, listed before the void, keeps every particle inside it.
  const VoidSpec& v = carvedScene.voids[0];
  std::size_t j = 0, removed = 0, plugInHole = 0;
  for (std::size_t i = 0; i < full.size(); ++i) {
    const bool isSlab = full.rho[i] == 1.0;
    const bool inHole = insideVoid(v, {full.x[0][i], full.x[1][i], full.x[2][i]}, 2);
    if (isSlab && inHole) {
      ++removed;
      continue;
    }
    plugInHole += (!isSlab && inHole) ? 1 : 0;
    ASSERT_LT(j, carved.size());
    ASSERT_TRUE(samePosition(full, i, carved, j)) << "particle " << i;
    EXPECT_EQ(full.mass[i], carved.mass[j]);
    EXPECT_EQ(full.h[i], carved.h[j]);
    EXPECT_EQ(full.u[i], carved.u[j]);
    EXPECT_EQ(full.material[i], carved.material[j]);
    ++j;
  }
  EXPECT_EQ(j, carved.size());
  // (pi 0.3^2 / 2 - pi 0.1^2) / 0.02^2 = 275 cells: the hole less the plug; the lattice points
  // in it differ by the cut cells along its 1.3 m edge (65 cells), far fewer as their errors
  // cancel: 5%.
  EXPECT_NEAR(static_cast<double>(removed), 275.0, 14.0);
  EXPECT_GT(plugInHole, 50u);    // the whole plug lies in the hole: pi 0.1^2 / 0.02^2 = 79
}

// The bowl's space against the paraboloid's exact size: the area 4/3 a d of a parabolic segment
// (planar) and the volume pi a^2 d / 2 of a paraboloid (RZ rings), counted as the particles it
// removes from a block whose top is the bowl's rim.
TEST(Bodies, BowlRemovesAParaboloidsVolume) {
  const double a = 0.8, d = 1.5, s = 0.01, rho = 1.0;
  const std::string bowl = voidBody("crater",
                                    "shape = \"paraboloid\"\npoint = [0, -1.5]\nnormal = [0, 1]\n"
                                    "radius = 0.8\ndepth = 1.5");
  {
    const std::string block = body("block", "shape = \"box\"\nmin = [-1, -2]\nmax = [1, 0]", s, rho);
    const double removed = totalMass(build("2d", block)) - totalMass(build("2d", bowl + block));
    // Points of a cubic lattice in a smooth convex region differ from area/s^2 by a boundary
    // term far below the perimeter's cell count (3.9 m / s = 390 cells, 2.4% of the 16,000 in
    // the segment) because the cut cells' errors cancel; measured 0.03%. 0.3% keeps a 10x margin.
    EXPECT_NEAR(removed / rho, 4.0 / 3.0 * a * d, 3e-3 * 4.0 / 3.0 * a * d);
  }
  {
    const std::string block = body("block", "shape = \"box\"\nmin = [0, -2]\nmax = [1, 0]", s, rho);
    const double removed = totalMass(build("rz", block)) - totalMass(build("rz", bowl + block));
    // The rings' masses integrate r exactly over each cell, so only the cut cells err, as above.
    const double volume = kPi * a * a * d / 2.0;
    EXPECT_NEAR(removed / rho, volume, 3e-3 * volume);
  }
}

TEST(Bodies, BowlInsideTestFollowsItsAxis) {
  // A 3D bowl opening along (1, 1, 0)/sqrt 2, floor at the origin, 1 wide at height 1.
  BowlSpec b;
  b.floor = {0, 0, 0};
  b.axis = {1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0};
  b.depth = 1.0;
  b.radius = 1.0;
  auto at = [&](double height, double off, const std::array<double, 3>& across) {
    return std::array<double, 3>{b.axis[0] * height + across[0] * off,
                                 b.axis[1] * height + across[1] * off, across[2] * off};
  };
  const std::array<double, 3> side{1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0}, up{0, 0, 1};
  // radius(height) = sqrt(height): inside just within it, outside just beyond, in both directions
  // across the axis; nothing below the floor; open above the rim height.
  for (double height : {0.25, 1.0, 4.0})
    for (const auto& dir : {side, up}) {
      EXPECT_TRUE(insideBowl(b, at(height, 0.999 * std::sqrt(height), dir), 3));
      EXPECT_FALSE(insideBowl(b, at(height, 1.001 * std::sqrt(height), dir), 3));
    }
  EXPECT_TRUE(insideBowl(b, {0, 0, 0}, 3));
  EXPECT_FALSE(insideBowl(b, at(-0.01, 0.0, up), 3));
}

TEST(Bodies, VoidErrorsNameTheKey) {
  const std::string slab = body("slab", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]", 0.1, 1.0);
  const std::string sphereHole =
      voidBody("hole", "shape = \"sphere\"\ncenter = [0.5, 1.0]\nradius = 0.3");
  auto expectError = [](const std::string& msg, const std::string& fragment) {
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
  };
  expectError(errorOf("2d", voidBody("hole", "shape = \"sphere\"\ncenter = [0.5, 1.0]\n"
                                             "radius = 0.3\nmaterial = \"gas\"") + slab),
              "key 'bodies[0].material': a void body makes no particles");
  expectError(errorOf("2d", slab + sphereHole),
              "void body 'hole' is listed after every body and carves nothing");
  expectError(errorOf("2d", sphereHole), "every [[bodies]] entry is a void");
  expectError(errorOf("2d", sphereHole + body("hole", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]",
                                              0.1, 1.0)),
              "key 'bodies[1].name': 'hole' is already used");
  expectError(errorOf("2d", body("slab", "shape = \"paraboloid\"\npoint = [0, 0]\nnormal = [0, 1]\n"
                                         "radius = 1\ndepth = 1", 0.1, 1.0)),
              "key 'bodies[0].shape': shape 'paraboloid' is for void bodies only");
  expectError(errorOf("2d", body("slab", "shape = \"box\"\nmin = [0, 0]\nmax = [1, 1]\ndepth = 1",
                                 0.1, 1.0)),
              "key 'bodies[0].depth': only a void body's shape 'paraboloid' takes a depth");
  expectError(errorOf("2d", voidBody("hole", "shape = \"sphere\"\ncenter = [0.5, 1.0]\n"
                                             "radius = 0.3\ndepth = 1") + slab),
              "key 'bodies[0].depth': only shape 'paraboloid' takes a depth");
  expectError(errorOf("2d", voidBody("hole", "shape = \"paraboloid\"\npoint = [0.5, 0.5]\n"
                                             "normal = [0, 1]\nradius = 0.3") + slab),
              "key 'bodies[0].depth': required key is missing");
  expectError(errorOf("2d", voidBody("hole", "shape = \"paraboloid\"\npoint = [0.5, 0.5]\n"
                                             "normal = [0, 1]\nradius = 0.3\ndepth = \"-1 m\"") + slab),
              "key 'bodies[0].depth': must be positive");
  expectError(errorOf("2d", voidBody("hole", "shape = \"paraboloid\"\npoint = [0.5, 0.5]\n"
                                             "normal = [0, 0]\nradius = 0.3\ndepth = 1") + slab),
              "key 'bodies[0].normal': must not be the zero vector");
  expectError(errorOf("2d", voidBody("hole", "shape = \"paraboloid\"\ncenter = [0.5, 0.5]\n"
                                             "point = [0.5, 0.5]\nnormal = [0, 1]\nradius = 0.3\n"
                                             "depth = 1") + slab),
              "key 'bodies[0].center': not used by shape 'paraboloid'");
  expectError(errorOf("rz", voidBody("hole", "shape = \"paraboloid\"\npoint = [0.2, 0.5]\n"
                                             "normal = [0, 1]\nradius = 0.3\ndepth = 1") + slab),
              "key 'bodies[0].point': in rz a paraboloid's floor must be on the axis");
  expectError(errorOf("rz", voidBody("hole", "shape = \"paraboloid\"\npoint = [0, 0.5]\n"
                                             "normal = [1, 1]\nradius = 0.3\ndepth = 1") + slab),
              "key 'bodies[0].normal': in rz a paraboloid must open along the axis");
  expectError(errorOf("2d", sphereHole + slab +
                                "[[energy_deposits]]\nname = \"yield\"\nenergy = 1\nbody = \"hole\"\n"),
              "key 'energy_deposits[0].body': 'hole' is a void body: it has no particles");
  // Messages about bodies count the file's entries, voids included.
  expectError(errorOf("2d", voidBody("all", "shape = \"box\"\nmin = [-1, -1]\nmax = [2, 2]") + slab),
              "key 'bodies[1]': body 'slab': produces no particles (the shape is outside the "
              "domain, covered by earlier bodies or voids");
}

// The study scenes (docs/asteroid_studies.md) load and build, every variant of the sweeps their
// headers give included, and the crater void reproduces the crater it was cut to: measured by
// ejecta's own crater analysis (fields/measure_crater), impact_rz's 6.47 m depth and 7.61 m
// apparent diameter, and impact_2d's 4.01 m and 9.05 m (docs/impact.md).
struct StudyScene {
  const char* file;
  const char* varied;                 // the header's --vary key
  std::vector<std::string> values;    // and its values
  double craterDepth = 0.0;           // 0: no crater
  double craterDiameter = 0.0;
};

TEST(Bodies, StudyScenesBuild) {
  const std::filesystem::path dir = std::filesystem::path(EJECTA_SOURCE_DIR) / "scenes";
  const std::vector<StudyScene> scenes{
      {"asteroid_contact_100kt_rz.toml", "energy_deposits[0].energy", {"100 kt", "250 kt"}},
      {"asteroid_subsurface_100kt_rz.toml", "energy_deposits[0].energy", {"100 kt", "250 kt"},
       6.47, 7.61},
      {"case1_2d.toml", "bodies[0].center",
       {"[0.0, \"31.99 m\"]", "[\"0.751 m\", \"32.147 m\"]", "[\"1.628 m\", \"32.692 m\"]",
        "[\"2.617 m\", \"33.711 m\"]", "[\"3.671 m\", \"35.226 m\"]"},
       4.01, 9.05},
      {"case2_rz.toml", "bodies[0].center",
       {"[0.0, \"26.53 m\"]", "[0.0, \"29.53 m\"]", "[0.0, \"32.03 m\"]", "[0.0, \"34.79 m\"]",
        "[0.0, \"38.53 m\"]"},
       6.47, 7.61}};
  for (const StudyScene& study : scenes) {
    SCOPED_TRACE(study.file);
    const std::string path = (dir / study.file).string();
    for (const std::string& value : study.values) {
      SCOPED_TRACE(value);
      const Scene s = loadScene(path, {std::string(study.varied) + "=" + value});
      const ParticleSet p = build(s);
      // The device (material "device") holds the yield: it starts at e = 0 (Tillotson at the
      // reference density and zero pressure), and the deposit adds exactly E up to the rounding
      // of a sum over some ten particles (1e-12 relative).
      const auto device = std::find_if(s.materials.begin(), s.materials.end(),
                                       [](const MaterialSpec& m) { return m.name == "device"; });
      ASSERT_NE(device, s.materials.end());
      const int deviceIndex = static_cast<int>(device - s.materials.begin());
      double yield = 0.0;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (p.material[i] == deviceIndex) yield += p.mass[i] * p.u[i];
      EXPECT_NEAR(yield, s.deposits.at(0).energy, 1e-12 * s.deposits.at(0).energy);
      // No target particle in the crater.
      const int dim = spatialDimension(s.geometry);
      for (std::size_t i = 0; i < p.size(); ++i) {
        if (p.material[i] == deviceIndex) continue;
        for (const VoidSpec& v : s.voids)
          ASSERT_FALSE(insideVoid(v, {p.x[0][i], p.x[1][i], p.x[2][i]}, dim)) << "particle " << i;
      }
    }
    if (study.craterDepth == 0.0) continue;
    // At 0.25 m (the spacing of the impact runs that measured the crater).
    std::vector<std::string> fine;
    for (int b : {0, 2, 3}) fine.push_back("bodies[" + std::to_string(b) + "].spacing=0.25 m");
    const Scene s = loadScene(path, fine);
    ASSERT_EQ(s.voids.size(), 1u);
    const ParticleSet p = build(s);
    // The measurement of fields/measure_crater.cpp (the target splatted onto a lattice, rays from
    // the original sphere), with the level tolerance at half a spacing: the surface of a lattice
    // cut to a sphere is a staircase that lies up to half a spacing off the sphere, so the
    // default (a quarter of the resolution) never sees an untouched lattice as "at the level".
    fields::CraterOptions options;
    options.surface.kind = fields::ReferenceSurface::Kind::Sphere;
    options.surface.center = {0, 0, 0};
    options.surface.radius = 35.0;
    options.impactPoint = {0, 35.0, 0};
    options.planar = s.geometry == Geometry::Planar;
    const double spacing = 0.25;
    options.resolution = 0.5 * fields::medianSmoothingLength(p);
    options.levelTolerance = 0.5 * spacing;
    std::vector<double> target(p.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i)
      target[i] = s.materials[static_cast<std::size_t>(p.material[i])].name == "device" ? 0.0 : 1.0;
    const fields::SparseLattice lattice = fields::splatParticles(
        p, fields::ParticleContext::fromScene(s), {target}, options.resolution);
    const bool rz = s.geometry == Geometry::Axisymmetric;
    const fields::CraterMetrics c = fields::analyseCrater(
        [&](const fields::Point& x) {
          return lattice.sample(1, rz ? fields::Point{std::hypot(x[0], x[2]), x[1], 0.0} : x);
        },
        options);
    ASSERT_TRUE(c.found) << c.note;
    // The lattice meets the bowl to within half a spacing, the level to within another half, and
    // the measurement adds up to a spacing (tests/fields/test_crater_particles.cpp): one spacing on the
    // depth, two on the diameter (a spacing on each side).
    EXPECT_NEAR(c.depth, study.craterDepth, spacing);
    EXPECT_NEAR(c.apparentDiameter, study.craterDiameter, 2 * spacing);
    std::printf("[ measured ] %s crater at 0.25 m: depth %.3f m, apparent diameter %.3f m\n",
                study.file, c.depth, c.apparentDiameter);
  }
}

}  // namespace
}  // namespace ejecta

namespace ejecta {
namespace {

// The nearest pair of particles of material `a` and any other: the gap between two bodies.
double nearestPair(const ParticleSet& p, int a, int dim) {
  double best = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.material[i] != a) continue;
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (p.material[j] == a) continue;
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) r2 += std::pow(p.x[d][i] - p.x[d][j], 2);
      best = std::min(best, r2);
    }
  }
  return std::sqrt(best);
}

// The floor the resting bodies meet: a 10 m box, 2D, its top at y = 10.
std::string floorBox(double spacing = 1.0) {
  return body("floor", "shape = \"box\"\nmin = [0, 0]\nmax = [10, 10]", spacing, 1.0);
}

// A disc of its own material over a floor, 2D; `rest` adds the rest keys to the disc.
std::string discOnFloor(double spacing, const std::string& rest) {
  return sceneText("2d", "[[materials]]\nname = \"disc\"\ngamma = 1.4\n") +
         "[[bodies]]\nname = \"disc\"\nmaterial = \"disc\"\nshape = \"sphere\"\ncenter = [5.3, 12]\n"
         "radius = 2\nspacing = " + std::to_string(spacing) + "\ndensity = 1\npressure = 1\n" + rest +
         floorBox(spacing);
}

TEST(RestingBodies, ADiscComesToRestOneSpacingAboveTheFloorWorkedByHand) {
  // Spacing 1: the disc's lowest row is y = 12 - 1.5 = 10.5 at x = 4.8 and 5.8 (the points
  // +-1.5 are outside the radius); the floor's top row is y = 9.5 at x = 0.5, 1.5, ..., 9.5, so
  // the nearest pairs are 0.3 apart across: one spacing apart when the rows are sqrt(1 - 0.09)
  // apart, and the disc moves down (along rest_direction) 10.5 - 9.5 - 0.953939 = 0.046061 m.
  const Scene s = parseScene(discOnFloor(1.0, "rest_on = \"floor\"\n"), "t.toml");
  EXPECT_NEAR(s.bodies[0].restMove, 1.0 - std::sqrt(1.0 - 0.09), 1e-12);
  EXPECT_NEAR(s.bodies[0].shape.center[1], 12.0 - (1.0 - std::sqrt(1.0 - 0.09)), 1e-12);
  EXPECT_NEAR(nearestPair(build(s), 1, 2), 1.0, 1e-12);
  // rest_gap in spacings, and a direction other than down (the disc moved up to a ceiling).
  EXPECT_NEAR(nearestPair(build(parseScene(discOnFloor(1.0, "rest_on = \"floor\"\nrest_gap = 1.5\n"),
                                           "t.toml")), 1, 2),
              1.5, 1e-12);
  const std::string ceiling =
      sceneText("2d", "[[materials]]\nname = \"disc\"\ngamma = 1.4\n") +
      "[[bodies]]\nname = \"disc\"\nmaterial = \"disc\"\nshape = \"sphere\"\ncenter = [5.3, -2.2]\n"
      "radius = 2\nspacing = 0.5\ndensity = 1\npressure = 1\nrest_on = \"roof\"\nrest_direction = [0, 3]\n" +
      body("roof", "shape = \"box\"\nmin = [0, 0]\nmax = [10, 10]", 0.5, 1.0);
  const Scene up = parseScene(ceiling, "t.toml");
  EXPECT_GT(up.bodies[0].restMove, 0.0);
  EXPECT_NEAR(nearestPair(build(up), 1, 2), 0.5, 1e-12);
}

TEST(RestingBodies, TheRunsSummaryGivesHowFarEachRestingBodyMoved) {
  // summary.json's rest_move_<body>_m is the move the worked case above gives, for the body
  // that rests and for no other.
  const Scene s = parseScene(discOnFloor(1.0, "rest_on = \"floor\"\n"), "t.toml", {"time.t_end=1e-9"});
  RunOptions options;
  options.threads = 1;
  const RunOutcome r = runScene(s, options);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NEAR(r.summary.number("rest_move_disc_m"), 1.0 - std::sqrt(1.0 - 0.09), 1e-12);
  EXPECT_FALSE(r.summary.has("rest_move_floor_m"));
}

TEST(RestingBodies, TheCraterFloorDeviceMeetsTheFloorAtOneSpacingAtEverySpacing) {
  // The shipped crater-floor burst: placed by its centre, the device's nearest crust particle is
  // 1.0 spacing away at 0.5 m but 0.52 at 0.354 m (docs/asteroid_studies.md); resting, it is one
  // spacing at every level of the study (bench/headline.toml's crater_floor_100kt).
  const std::string path = (std::filesystem::path(EJECTA_SOURCE_DIR) / "scenes" /
                            "asteroid_subsurface_100kt_rz.toml").string();
  const auto spacing = [](double s) {
    std::vector<std::string> keys;
    for (int b : {0, 2, 3}) keys.push_back("bodies[" + std::to_string(b) + "].spacing=" + std::to_string(s));
    return keys;
  };
  const double placed = nearestPair(build(loadScene(path, spacing(0.3536))), 2, 2);
  EXPECT_LT(placed / 0.3536, 0.6) << "measured 0.52 spacing: the failure this key cures";
  for (double s : {0.5, 0.3536, 0.25, 0.1768}) {
    SCOPED_TRACE(s);
    std::vector<std::string> keys = spacing(s);
    keys.push_back("bodies[0].rest_on=\"crust\"");
    const Scene scene = loadScene(path, keys);
    EXPECT_LT(std::abs(scene.bodies[0].restMove), s);  // it was placed on the floor by hand
    EXPECT_NEAR(nearestPair(build(scene), 2, 2), s, 1e-9 * s);
  }
}

TEST(RestingBodies, ErrorsNameTheKeyAndTheReason) {
  auto expectError = [](const std::string& text, const std::string& fragment) {
    try {
      parseScene(text, "t.toml");
      ADD_FAILURE() << "no error; expected: " << fragment;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectError(discOnFloor(1.0, "rest_on = \"ground\"\n"), "key 'bodies[0].rest_on': body 'disc': no body named 'ground'");
  expectError(discOnFloor(1.0, "rest_on = \"disc\"\n"), "a body cannot rest on itself");
  expectError(discOnFloor(1.0, "rest_gap = 1\n"), "key 'bodies[0].rest_gap': applies only with rest_on");
  expectError(discOnFloor(1.0, "rest_on = \"floor\"\nrest_gap = 3\n"), "key 'bodies[0].rest_gap': must be in [1, 2]");
  expectError(discOnFloor(1.0, "rest_on = \"floor\"\nrest_gap = 1e-320\n"), "key 'bodies[0].rest_gap': must be in [1, 2]");
  expectError(discOnFloor(1.0, "rest_on = \"floor\"\nrest_direction = [0, 0]\n"),
              "key 'bodies[0].rest_direction': must be a finite vector, not zero");
  // Too far above the floor to be resting on it (4 spacings of search), or already inside it.
  expectError(sceneText("2d", "") + body("disc", "shape = \"sphere\"\ncenter = [5, 20]\nradius = 2\nrest_on = \"floor\"", 1.0, 1.0) +
                  floorBox(),
              "meets nothing of 'floor' within 4 m along rest_direction");
  expectError(sceneText("2d", "") + body("disc", "shape = \"sphere\"\ncenter = [5, 5]\nradius = 2\nrest_on = \"floor\"", 1.0, 1.0) +
                  floorBox(),
              "or inside it, even 4 m back against rest_direction");
  // One body on another, no chains; a body the domain cuts differently at its rest.
  expectError(sceneText("2d", "") +
                  body("a", "shape = \"sphere\"\ncenter = [5, 16]\nradius = 1\nrest_on = \"b\"", 1.0, 1.0) +
                  body("b", "shape = \"sphere\"\ncenter = [5, 12]\nradius = 2\nrest_on = \"floor\"", 1.0, 1.0) +
                  floorBox(),
              "'b' rests on a body itself");
  expectError(sceneText("2d", "") +
                  body("a", "shape = \"sphere\"\ncenter = [2.3, 12]\nradius = 1\nrest_on = \"floor\"", 1.0, 1.0) +
                  body("b", "shape = \"sphere\"\ncenter = [7.3, 12]\nradius = 2\nrest_on = \"floor\"", 1.0, 1.0) +
                  floorBox(),
              "key 'bodies[1].rest_on': body 'b': 'a' rests on 'floor' already");
  // The disc's row at y = 12.5 is outside a domain that ends at 12.48, and inside it once the
  // disc has moved down 0.046 m (the hand-worked case above).
  expectError(sceneText("2d", "[domain]\ny = { min = -1, max = 12.48 }\n[[materials]]\nname = \"disc\"\ngamma = 1.4\n") +
                  "[[bodies]]\nname = \"disc\"\nmaterial = \"disc\"\nshape = \"sphere\"\ncenter = [5.3, 12]\n"
                  "radius = 2\nspacing = 1\ndensity = 1\npressure = 1\nrest_on = \"floor\"\n" +
                  floorBox(),
              "cuts it differently than where it was placed");
  // Bounds on the work of a reader given any text: a resting body far finer than the other, or
  // with more particles than a device or an impactor has.
  expectError(sceneText("2d", "") + body("disc", "shape = \"sphere\"\ncenter = [5, 12]\nradius = 2\nrest_on = \"floor\"", 0.001, 1.0) +
                  floorBox(),
              "is too fine beside 'floor''s");
  expectError(sceneText("2d", "") + body("disc", "shape = \"sphere\"\ncenter = [5, 12]\nradius = 2\nrest_on = \"floor\"", 0.005, 1.0) +
                  body("floor", "shape = \"box\"\nmin = [0, 0]\nmax = [10, 10]", 0.005, 1.0),
              "key 'bodies[0].rest_on': body 'disc': placing it: t.toml:");
  // The resting body claims its place: it must come first.
  expectError(sceneText("2d", "") + floorBox() +
                  body("disc", "shape = \"sphere\"\ncenter = [5, 12]\nradius = 2\nrest_on = \"floor\"", 1.0, 1.0),
              "list it before 'floor'");
  expectError(sceneText("2d", "") + voidBody("pit", "shape = \"sphere\"\ncenter = [5, 10]\nradius = 1") +
                  body("disc", "shape = \"sphere\"\ncenter = [5, 12]\nradius = 2\nrest_on = \"pit\"", 1.0, 1.0) +
                  floorBox(),
              "'pit' is a void body");
  expectError(sceneText("2d", "[domain]\nx = { min = -20, max = 20 }\ny = { min = -20, max = 20 }\n") +
                  body("ground", "shape = \"half_space\"\npoint = [0, 0]\nnormal = [0, 1]\nrest_on = \"floor\"", 1.0, 1.0) +
                  floorBox(),
              "a half_space cannot be moved");
  expectError(sceneText("rz", "") + body("ball", "shape = \"sphere\"\ncenter = [0, 12]\nradius = 2\nrest_on = \"floor\"\nrest_direction = [1, -1]", 1.0, 1.0) +
                  floorBox(),
              "in rz a body can only move along the axis");
}

}  // namespace
}  // namespace ejecta
