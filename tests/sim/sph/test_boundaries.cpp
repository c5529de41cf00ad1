// Ghost particles: mirror images at walls (normal velocity reversed), periodic images, corner
// images from both, and confinement of particles that crossed a boundary during a drift.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/sph/boundaries.hpp"

namespace ejecta {
namespace {

std::array<AxisBounds, 3> wallXPeriodicY() {
  std::array<AxisBounds, 3> domain{};
  domain[0] = {0.0, 1.0, BoundaryKind::Wall, BoundaryKind::Wall, true};
  domain[1] = {0.0, 1.0, BoundaryKind::Periodic, BoundaryKind::Periodic, true};
  return domain;
}

// Index of the ghost at (x, y), or -1.
long findGhost(const ParticleSet& p, double x, double y) {
  for (std::size_t g = p.numReal; g < p.size(); ++g)
    if (std::abs(p.x[0][g] - x) < 1e-12 && std::abs(p.x[1][g] - y) < 1e-12)
      return static_cast<long>(g);
  return -1;
}

TEST(Boundaries, MirrorPeriodicAndCornerImages) {
  ParticleSet p;
  p.append({0.05, 0.5, 0}, {0.3, 0.2, 0}, 1, 1, 1, 0.02, 0);   // near the x = 0 wall only
  p.append({0.5, 0.97, 0}, {0.1, -0.4, 0}, 1, 1, 1, 0.02, 0);  // near the y = 1 periodic face
  p.append({0.02, 0.01, 0}, {-0.5, 0.6, 0}, 1, 1, 1, 0.02, 0); // near the corner (0, 0)
  p.append({0.5, 0.5, 0}, {0, 0, 0}, 1, 1, 1, 0.02, 0);        // interior: no image
  Boundaries b(Geometry::Planar, wallXPeriodicY());
  b.makeGhosts(p, 2.0);  // reach 2h = 0.04 from the faces (0.05 from x = 0 is outside it)

  EXPECT_EQ(findGhost(p, -0.05, 0.5), -1) << "particle 0 is beyond the layer";
  const long periodic = findGhost(p, 0.5, -0.03);
  ASSERT_GE(periodic, 0) << "periodic image of particle 1 below y = 0";
  EXPECT_DOUBLE_EQ(p.v[1][periodic], -0.4);  // periodic images keep their velocity
  const long mirror = findGhost(p, -0.02, 0.01);
  ASSERT_GE(mirror, 0);
  EXPECT_DOUBLE_EQ(p.v[0][mirror], 0.5);  // normal component reversed
  EXPECT_DOUBLE_EQ(p.v[1][mirror], 0.6);
  const long image = findGhost(p, 0.02, 1.01);
  ASSERT_GE(image, 0) << "periodic image of the corner particle above y = 1";
  const long corner = findGhost(p, -0.02, 1.01);
  ASSERT_GE(corner, 0) << "image of the mirror image fills the corner";
  EXPECT_DOUBLE_EQ(p.v[0][corner], 0.5);
  EXPECT_EQ(p.ghostSource[static_cast<std::size_t>(corner) - p.numReal], 2u);
  EXPECT_TRUE(b.layersCover(p, 2.0));

  // After the density pass changes a source, refreshing copies it (with the flips).
  p.v[0][2] = -0.7;
  p.rho[2] = 3.0;
  b.refreshGhosts(p);
  EXPECT_DOUBLE_EQ(p.v[0][corner], 0.7);
  EXPECT_DOUBLE_EQ(p.rho[corner], 3.0);
  // A particle whose h grew past the layer is detected.
  p.h[2] = 0.05;
  EXPECT_FALSE(b.layersCover(p, 2.0));
}

TEST(Boundaries, PeriodicLayerCoversTheFarSideOfTheSeam) {
  // Large h just below y = 1, small h just above y = 0: the images of the small-h particles
  // land beside y = 1 and must reach as deep as the large supports there.
  ParticleSet p;
  p.append({0.5, 0.01, 0}, {0, 0, 0}, 1, 1, 1, 0.005, 0);
  p.append({0.5, 0.08, 0}, {0, 0, 0}, 1, 1, 1, 0.005, 0);
  p.append({0.5, 0.95, 0}, {0, 0, 0}, 1, 1, 1, 0.05, 0);
  Boundaries b(Geometry::Planar, wallXPeriodicY());
  b.makeGhosts(p, 2.0);
  // Particle 2's support reaches 0.1 beyond y = 1, i.e. to y = 0.05 + 1: particle 1 at 0.08 is
  // not inside it (0.95 -> 1.08 is 0.13 away), particle 0 at 1.01 is.
  EXPECT_GE(findGhost(p, 0.5, 1.01), 0);
  EXPECT_GE(findGhost(p, 0.5, 1.08), 0) << "layer must be at least particle 2's reach (0.1)";
  EXPECT_TRUE(b.layersCover(p, 2.0));
}

TEST(Boundaries, ConfineReflectsAtWallsAndWrapsPeriodically) {
  ParticleSet p;
  p.append({-0.01, 1.02, 0}, {-1.0, 2.0, 0}, 1, 1, 1, 0.02, 0);
  Vec3Array half;
  for (auto& c : half) c = {-0.5};
  Boundaries b(Geometry::Planar, wallXPeriodicY());
  b.confine(p, &half);
  EXPECT_DOUBLE_EQ(p.x[0][0], 0.01);
  EXPECT_DOUBLE_EQ(p.v[0][0], 1.0);
  EXPECT_DOUBLE_EQ(half[0][0], 0.5);  // the leapfrog's half-step velocity is reflected too
  EXPECT_NEAR(p.x[1][0], 0.02, 1e-15);
  EXPECT_DOUBLE_EQ(p.v[1][0], 2.0);
}

TEST(Boundaries, AxisIsAMirrorInRZ) {
  std::array<AxisBounds, 3> domain{};
  domain[0] = {0.0, 1.0, BoundaryKind::Wall, BoundaryKind::Open, true};
  ParticleSet p;
  p.append({0.01, 0.3, 0}, {0.2, 0.1, 0}, 1, 1, 1, 0.02, 0);
  Boundaries b(Geometry::Axisymmetric, domain);
  b.makeGhosts(p, 2.0);
  const long g = findGhost(p, -0.01, 0.3);
  ASSERT_GE(g, 0);
  EXPECT_DOUBLE_EQ(p.v[0][g], -0.2);
  EXPECT_DOUBLE_EQ(p.v[1][g], 0.1);
  EXPECT_DOUBLE_EQ(p.mass[g], p.mass[0]);  // the same ring
}

}  // namespace
}  // namespace ejecta
