// Fragment identification (fields/fragments, issue 21): constructed cases with known answers
// (separated clumps, clumps joined by a failed seam, one body, RZ rings and bodies on the axis),
// conservation of mass and momentum over the fragments, the size-frequency table, and results
// that do not depend on the thread count.
#include <gtest/gtest.h>

#include <omp.h>

#include <cmath>
#include <numbers>

#include "fields/fragments.hpp"

namespace ejecta::fields {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRho = 2700.0;

// A ball of lattice particles (spacing dx, h = 1.2 dx) of radius R about c, moving at v, with
// the given damage; 3D, RZ (rings about the axis: c[0] is the section's centre radius) or
// planar (discs per metre).
void addBall(ParticleSet& p, Geometry g, std::array<double, 3> c, double R, double dx,
             std::array<double, 3> v, double damage = 0.0, int material = 0) {
  const int n = static_cast<int>(std::ceil(R / dx)) + 1;
  const bool three = g == Geometry::Spatial;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = three ? -n : 0; k <= (three ? n : 0); ++k) {
        const std::array<double, 3> x = {c[0] + (i + 0.5) * dx, c[1] + (j + 0.5) * dx,
                                         three ? c[2] + (k + 0.5) * dx : 0.0};
        const double r2 = (x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
                          (x[2] - c[2]) * (x[2] - c[2]);
        if (r2 > R * R) continue;
        if (g == Geometry::Axisymmetric && x[0] <= 0.0) continue;
        double m = kRho * std::pow(dx, spatialDimension(g));
        if (g == Geometry::Axisymmetric) m *= 2 * kPi * x[0];
        p.append(x, v, m, kRho, 0.0, 1.2 * dx, material);
        if (p.hasFracture()) p.crack.back() = std::cbrt(damage);
      }
  p.numReal = p.size();
}

ParticleSet fracturing() {
  ParticleSet p;
  p.enableFracture();
  return p;
}

void expectConserved(const ParticleSet& p, const FragmentCensus& c, int dim) {
  double mass = 0.0;
  std::array<double, 3> momentum{}, fromParticles{};
  for (const Fragment& f : c.fragments) {
    mass += f.mass;
    for (int d = 0; d < dim; ++d) momentum[d] += f.mass * f.velocity[d];
  }
  double particleMass = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    particleMass += p.mass[i];
    for (int d = 0; d < dim; ++d) fromParticles[d] += p.mass[i] * p.v[d][i];
  }
  // Sums of the same terms in another order: equal to a few ulps of the total.
  EXPECT_NEAR(mass, particleMass, 1e-12 * particleMass);
  EXPECT_NEAR(c.totalMass, particleMass, 1e-12 * particleMass);
  for (int d = 0; d < dim; ++d) {
    const double scale = 1e-12 * particleMass * 1e3;
    EXPECT_NEAR(momentum[d], fromParticles[d], scale);
    EXPECT_NEAR(c.totalMomentum[d], fromParticles[d], scale);
  }
}

TEST(Fragments, SeparatedClumpsAreTwoFragmentsWithTheirOwnMassAndVelocity) {
  const double dx = 1e-3;
  ParticleSet p = fracturing();
  addBall(p, Geometry::Spatial, {0, 0, 0}, 5e-3, dx, {100, 0, 0});
  const std::size_t first = p.size();
  addBall(p, Geometry::Spatial, {20e-3, 0, 0}, 3e-3, dx, {-50, 20, 0}, 0.0, 1);
  const FragmentCensus c = identifyFragments(p, Geometry::Spatial);
  ASSERT_EQ(c.fragments.size(), 2u);
  const Fragment& big = c.fragments[0];
  const Fragment& small = c.fragments[1];
  EXPECT_EQ(big.particles, first);
  EXPECT_EQ(small.particles, p.size() - first);
  EXPECT_EQ(big.material, 0);
  EXPECT_EQ(small.material, 1);
  EXPECT_NEAR(big.velocity[0], 100.0, 1e-12);
  EXPECT_NEAR(small.velocity[0], -50.0, 1e-12);
  EXPECT_NEAR(small.velocity[1], 20.0, 1e-12);
  EXPECT_NEAR(small.speed, std::hypot(50.0, 20.0), 1e-12);
  // A lattice ball's volume is its particle count times dx^3: the equivalent diameter is the
  // sphere's to within the lattice's staircase, a few per cent at 5 spacings of radius.
  EXPECT_NEAR(big.diameter, 10e-3, 0.05 * 10e-3);
  EXPECT_NEAR(big.spacing, dx, 1e-12);
  EXPECT_TRUE(big.resolved);    // 10 spacings across
  EXPECT_TRUE(small.resolved);  // 6 spacings
  EXPECT_NEAR(big.center[0], 0.0, 0.5 * dx);
  EXPECT_EQ(c.fragmentOf.front(), 0u);
  EXPECT_EQ(c.fragmentOf.back(), 1u);
  expectConserved(p, c, 3);
}

TEST(Fragments, ClumpsCloserThanTheKernelSupportAreOneBody) {
  // A gap of 1.5 dx between the nearest particles: the 2h = 2.4 dx supports overlap, so SPH still couples the
  // two and they are one fragment; at the default link they separate only beyond 2.4 dx.
  const double dx = 1e-3;
  ParticleSet p;
  addBall(p, Geometry::Spatial, {0, 0, 0}, 4e-3, dx, {});
  addBall(p, Geometry::Spatial, {8.5e-3, 0, 0}, 4e-3, dx, {});
  EXPECT_EQ(identifyFragments(p, Geometry::Spatial).fragments.size(), 1u);
  FragmentOptions tight;
  tight.linkFactor = 1.0;  // friends only within 1.2 dx: the gap splits them
  EXPECT_EQ(identifyFragments(p, Geometry::Spatial, tight).fragments.size(), 2u);
}

TEST(Fragments, AFailedSeamSeparatesTwoIntactPieces) {
  // A bar 20 x 6 x 6 spacings whose middle two layers have failed: two intact halves, and each
  // failed particle a fragment of its own.
  const double dx = 1e-3;
  ParticleSet p = fracturing();
  std::size_t seam = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) {
        p.append({(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx}, {}, kRho * dx * dx * dx, kRho,
                 0.0, 1.2 * dx, 0);
        const bool failed = i == 9 || i == 10;
        p.crack.back() = failed ? 1.0 : 0.2;  // intact: D = 0.008
        seam += failed;
      }
  p.numReal = p.size();
  const FragmentCensus c = identifyFragments(p, Geometry::Spatial);
  ASSERT_EQ(c.fragments.size(), 2 + seam);
  EXPECT_EQ(c.fragments[0].particles, 9u * 36u);
  EXPECT_EQ(c.fragments[1].particles, 9u * 36u);
  EXPECT_FALSE(c.fragments[0].failed);
  EXPECT_EQ(c.failedCount(), seam);
  EXPECT_FALSE(c.fragments.back().resolved);
  EXPECT_NEAR(c.fragments[0].meanDamage, 0.008, 1e-12);
  // Half the particles a step short of failure (D = 0.95) still link at the default threshold.
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.crack[i] == 1.0) p.crack[i] = std::cbrt(0.95);
  EXPECT_EQ(identifyFragments(p, Geometry::Spatial).fragments.size(), 1u);
  // With a threshold above 1 nothing fails: one body.
  for (std::size_t i = 0; i < p.size(); ++i) p.crack[i] = 1.0;
  FragmentOptions never;
  never.damageThreshold = 1.5;
  EXPECT_EQ(identifyFragments(p, Geometry::Spatial, never).fragments.size(), 1u);
  expectConserved(p, c, 3);
}

TEST(Fragments, ASingleBodyIsOneFragmentHoldingEveryParticle) {
  ParticleSet p;
  addBall(p, Geometry::Spatial, {1, 2, 3}, 6e-3, 1e-3, {0, 0, -3000});
  const FragmentCensus c = identifyFragments(p, Geometry::Spatial);
  ASSERT_EQ(c.fragments.size(), 1u);
  EXPECT_EQ(c.fragments[0].particles, p.size());
  EXPECT_NEAR(c.fragments[0].velocity[2], -3000.0, 1e-9);
  EXPECT_NEAR(c.fragments[0].kineticEnergy, 0.5 * c.totalMass * 9e6, 1e-9 * c.totalMass * 9e6);
  EXPECT_EQ(c.resolvedCount(), 1u);
}

TEST(Fragments, RzBodiesOnTheAxisAndRingsAreSizedApart) {
  const double dx = 1e-3;
  ParticleSet p;
  // A sphere on the axis (radius 5 mm), sized as a body of revolution.
  addBall(p, Geometry::Axisymmetric, {0, 0, 0}, 5e-3, dx, {0, 500, 0});
  // A ring whose section is a disc of radius 2.5 mm centred 30 mm from the axis.
  addBall(p, Geometry::Axisymmetric, {30e-3, 0, 0}, 2.5e-3, dx, {200, 0, 0});
  const FragmentCensus c = identifyFragments(p, Geometry::Axisymmetric);
  ASSERT_EQ(c.fragments.size(), 2u);
  const Fragment* sphere = &c.fragments[0];
  const Fragment* ring = &c.fragments[1];
  if (sphere->ring) std::swap(sphere, ring);
  EXPECT_FALSE(sphere->ring);
  EXPECT_TRUE(ring->ring);
  // Ring volumes summed: the sphere's 4/3 pi R^3 to the lattice's staircase.
  EXPECT_NEAR(sphere->diameter, 10e-3, 0.05 * 10e-3);
  EXPECT_NEAR(sphere->spacing, dx, 0.05 * dx);
  // The ring's section: pi (2.5 mm)^2 to the staircase; its volume 2 pi r A by Pappus, r the
  // section's centroid, which the mass-weighted centre (mass grows with r) passes by
  // ~(2.5 mm)^2 / (4 x 30 mm): 0.2% here.
  EXPECT_NEAR(ring->diameter, 5e-3, 0.1 * 5e-3);
  EXPECT_NEAR(ring->section, ring->volume / (2 * kPi * ring->center[0]), 3e-3 * ring->section);
  EXPECT_NEAR(ring->velocity[0], 200.0, 1e-9);
  EXPECT_TRUE(ring->resolved);  // 5 spacings across
  expectConserved(p, c, 2);
}

TEST(Fragments, PlanarRodsAreSizedByTheirSection) {
  const double dx = 1e-3;
  ParticleSet p;
  addBall(p, Geometry::Planar, {0, 0, 0}, 3e-3, dx, {10, 0, 0});
  const FragmentCensus c = identifyFragments(p, Geometry::Planar);
  ASSERT_EQ(c.fragments.size(), 1u);
  EXPECT_NEAR(c.fragments[0].section, static_cast<double>(p.size()) * dx * dx, 1e-15);
  EXPECT_NEAR(c.fragments[0].diameter, 6e-3, 0.08 * 6e-3);
  EXPECT_FALSE(c.fragments[0].ring);
}

TEST(Fragments, TheSameForAnyThreadCount) {
  // Many small clumps and loose failed particles in one cloud, at 1 and at 2 threads.
  const double dx = 1e-3;
  ParticleSet p = fracturing();
  for (int k = 0; k < 40; ++k) {
    const double a = 0.7 * k;
    addBall(p, Geometry::Spatial, {std::cos(a) * (10e-3 + 2e-3 * k), std::sin(a) * (10e-3 + 2e-3 * k), 0.0},
            (1.0 + (k % 4)) * dx, dx, {10.0 * k, -5.0 * k, 1.0}, (k % 3 == 0) ? 1.0 : 0.0);
  }
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const FragmentCensus one = identifyFragments(p, Geometry::Spatial);
  omp_set_num_threads(2);
  const FragmentCensus two = identifyFragments(p, Geometry::Spatial);
  omp_set_num_threads(threads);
  ASSERT_EQ(one.fragments.size(), two.fragments.size());
  EXPECT_EQ(one.fragmentOf, two.fragmentOf);
  for (std::size_t k = 0; k < one.fragments.size(); ++k) {
    EXPECT_EQ(one.fragments[k].firstId, two.fragments[k].firstId);
    EXPECT_EQ(one.fragments[k].mass, two.fragments[k].mass);
    EXPECT_EQ(one.fragments[k].velocity, two.fragments[k].velocity);
  }
  expectConserved(p, one, 3);
}

TEST(Fragments, SizeFrequencyCountsFragmentsAtLeastEachSize) {
  const double dx = 1e-3;
  ParticleSet p = fracturing();
  addBall(p, Geometry::Spatial, {0, 0, 0}, 5e-3, dx, {});
  addBall(p, Geometry::Spatial, {30e-3, 0, 0}, 3e-3, dx, {});
  addBall(p, Geometry::Spatial, {60e-3, 0, 0}, 3e-3, dx, {});
  addBall(p, Geometry::Spatial, {90e-3, 0, 0}, 1e-3, dx, {}, 1.0);  // failed: 8 loose particles
  const FragmentCensus c = identifyFragments(p, Geometry::Spatial);
  const auto rows = sizeFrequency(c);
  // 5 mm, then the two 3 mm balls (one diameter, one row), then the loose particles.
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows[0].countAtLeast, 1u);
  EXPECT_EQ(rows[1].countAtLeast, 3u);
  EXPECT_EQ(rows[1].measuredCountAtLeast, 3u);
  EXPECT_NEAR(rows[1].massAtLeast, c.fragments[0].mass + c.fragments[1].mass + c.fragments[2].mass, 1e-15);
  EXPECT_EQ(rows.back().countAtLeast, c.fragments.size());
  EXPECT_EQ(rows.back().measuredCountAtLeast, 3u);  // the loose particles' sizes are not measured
  EXPECT_NEAR(rows.back().massAtLeast, c.totalMass, 1e-12 * c.totalMass);
  EXPECT_NEAR(rows.back().measuredMassAtLeast, rows[1].massAtLeast, 1e-15);
  const std::string csv = fragmentsCsv(c, {"al"});
  EXPECT_NE(csv.find("index,particles,first_id,material,mass_kg"), std::string::npos);
  EXPECT_NE(csv.find(",al,"), std::string::npos);
}

TEST(Fragments, RefusesWhatItCannotMeasure) {
  ParticleSet p;
  addBall(p, Geometry::Spatial, {0, 0, 0}, 2e-3, 1e-3, {});
  EXPECT_THROW(identifyFragments(p, Geometry::Line), std::invalid_argument);
  FragmentOptions bad;
  bad.linkFactor = 0.0;
  EXPECT_THROW(identifyFragments(p, Geometry::Spatial, bad), std::invalid_argument);
  p.h[3] = -1.0;
  EXPECT_THROW(identifyFragments(p, Geometry::Spatial), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::fields
