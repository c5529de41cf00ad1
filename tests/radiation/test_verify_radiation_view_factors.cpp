// Monte Carlo view factors against exact configuration factors (docs/view_factors.md):
//   J. R. Howell, "A Catalog of Radiation Heat Transfer Configuration Factors", 3rd ed. (online,
//   thermalradiation.net): C-41 disc to parallel coaxial disc, C-11 identical directly opposed
//   rectangles, C-14 perpendicular rectangles with a common edge, B-13 planar element to a
//   circular disc (its first case, the element's plane not cutting the disc); and
//   M. F. Modest, "Radiative Heat Transfer", 3rd ed. (2013), Appendix D, configurations 12
//   (element to parallel coaxial disc), 16 and 18 (element to sphere, on and off its normal),
//   38 (opposed rectangles), 39 (perpendicular rectangles), 40 (coaxial discs).
// Each value is checked to 1e-3 at a ray count where 1e-3 is at least 4 standard errors (the
// test also asserts that the reported error is that small), plus reciprocity, closure inside an
// enclosure and a sphere, the flux from a hot sphere, the solid angle of a sphere, and that the
// reported standard error is honest (the error / standard error ratio over many seeds behaves
// as a t-distributed variable).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "radiation/spacecraft.hpp"
#include "radiation/view_factors.hpp"

namespace ejecta::radiation {
namespace {

constexpr double kPi = std::numbers::pi;
// The catalog tolerance of the issue: every factor within 1e-3 of the exact value.
constexpr double kTolerance = 1e-3;
// 1e-3 must be at least 4 standard errors at the chosen ray count.
constexpr double kMaxStandardError = kTolerance / 4.0;
// Segments of the disc polygons; makeDisc keeps the exact area, the remaining shape error of a
// 512-gon changes these factors by ~1e-6.
constexpr int kDiscSegments = 512;

// ------------------------------------------------------------------ exact configuration factors

// Howell C-41 / Modest D-40: disc of radius r1 to a parallel coaxial disc of radius r2 at h.
double coaxialDiscs(double r1, double r2, double h) {
  const double R1 = r1 / h, R2 = r2 / h;
  const double X = 1.0 + (1.0 + R2 * R2) / (R1 * R1);
  return 0.5 * (X - std::sqrt(X * X - 4.0 * (R2 / R1) * (R2 / R1)));
}

// Howell C-11 / Modest D-38: identical, parallel, directly opposed a x b rectangles at c.
double opposedRectangles(double a, double b, double c) {
  const double X = a / c, Y = b / c;
  const double rx = std::sqrt(1.0 + X * X), ry = std::sqrt(1.0 + Y * Y);
  return 2.0 / (kPi * X * Y) *
         (std::log(rx * ry / std::sqrt(1.0 + X * X + Y * Y)) + X * ry * std::atan(X / ry) +
          Y * rx * std::atan(Y / rx) - X * std::atan(X) - Y * std::atan(Y));
}

// Howell C-14 / Modest D-39: from rectangle 1 (l x w) to rectangle 2 (l x h), sharing the edge l,
// at 90 degrees.
double perpendicularRectangles(double l, double w, double h) {
  const double H = h / l, W = w / l, H2 = H * H, W2 = W * W, HW2 = H2 + W2;
  const double a = (1.0 + W2) * (1.0 + H2) / (1.0 + W2 + H2);
  const double b = W2 * (1.0 + W2 + H2) / ((1.0 + W2) * HW2);
  const double c = H2 * (1.0 + H2 + W2) / ((1.0 + H2) * HW2);
  return (W * std::atan(1.0 / W) + H * std::atan(1.0 / H) - std::sqrt(HW2) * std::atan(1.0 / std::sqrt(HW2)) +
          0.25 * (std::log(a) + W2 * std::log(b) + H2 * std::log(c))) /
         (kPi * W);
}

// Modest D-16 and D-18: element at distance d from the centre of a sphere of radius R, its normal
// at angle phi to the line to the centre (phi <= acos(R/d): the whole sphere above its plane).
double elementToSphere(double R, double d, double phi) { return (R / d) * (R / d) * std::cos(phi); }

// Modest D-12 and Howell B-13 (first case): element on the axis of a disc of radius r at
// distance h, tilted by omega with its plane clear of the disc (tan omega <= h / r).
double elementToDisc(double r, double h, double omega) { return r * r / (r * r + h * h) * std::cos(omega); }

// ------------------------------------------------------------------------------------ helpers

SamplingOptions fixedRays(std::uint64_t rays, std::uint64_t seed = 7) {
  SamplingOptions o;
  o.rays = rays;
  o.seed = seed;
  return o;
}

// Checks one factor against its exact value: within 1e-3, and with a standard error small
// enough that 1e-3 is >= 4 of them. Prints the numbers for docs/view_factors.md.
void expectCatalog(const char* name, const Estimate& e, double exact, std::uint64_t rays) {
  const double err = e.value - exact;
  std::printf("  %-44s exact %.6f  MC %.6f  error %+.2e  std error %.2e  (%llu rays)\n", name, exact,
              e.value, err, e.standardError, static_cast<unsigned long long>(rays));
  EXPECT_LT(std::abs(err), kTolerance) << name;
  EXPECT_LE(e.standardError, kMaxStandardError) << name;
  EXPECT_GT(e.standardError, 0.0) << name << ": a zero error estimate for a fractional factor";
}

TriangleMesh twoDiscs(double r1, double r2, double h) {
  TriangleMesh m = makeDisc("disc1", {0, 0, 0}, {0, 0, 1}, r1, kDiscSegments);
  m.append(makeDisc("disc2", {0, 0, h}, {0, 0, -1}, r2, kDiscSegments));
  return m;
}

// ------------------------------------------------------------------------------------- tests

TEST(ViewFactorCatalog, ExactFormulasMatchPublishedValues) {
  // Guards the formulas themselves with values printed in the literature (EES heat transfer
  // library examples: F3D_3 for C-41 gives 0.1339, F3D_1 for C-11 gives 0.4756) and with the
  // cube identity: opposite + 4 adjacent faces = 1.
  EXPECT_NEAR(coaxialDiscs(0.1, 0.2, 0.5), 0.1339, 5e-5);
  EXPECT_NEAR(opposedRectangles(1.0, 1.5, 0.5), 0.4756, 5e-5);
  EXPECT_NEAR(opposedRectangles(1.0, 1.0, 1.0) + 4.0 * perpendicularRectangles(1.0, 1.0, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(perpendicularRectangles(1.0, 1.0, 1.0), 0.2000438, 1e-6);
}

TEST(ViewFactorCatalog, CoaxialDiscsAndReciprocity) {
  const double r1 = 0.5, r2 = 1.0, h = 1.0;
  const std::uint64_t rays = 1u << 20;
  const ViewFactorSolver solver(RadiationScene{twoDiscs(r1, r2, h), {}, {}});
  const ReceiverResult from1 = solver.fromPatch("disc1", fixedRays(rays));
  const ReceiverResult from2 = solver.fromPatch("disc2", fixedRays(rays));
  const double f12 = coaxialDiscs(r1, r2, h), f21 = coaxialDiscs(r2, r1, h);
  expectCatalog("C-41 coaxial discs r1=0.5 r2=1 h=1, F12", from1.toPatch[1], f12, from1.rays);
  expectCatalog("C-41 coaxial discs, F21", from2.toPatch[0], f21, from2.rays);
  // Reciprocity A1 F12 = A2 F21, within 4 combined standard errors (independent estimates).
  const double a1 = kPi * r1 * r1, a2 = kPi * r2 * r2;
  const double lhs = a1 * from1.toPatch[1].value, rhs = a2 * from2.toPatch[0].value;
  const double se = std::hypot(a1 * from1.toPatch[1].standardError, a2 * from2.toPatch[0].standardError);
  std::printf("  reciprocity A1 F12 = %.6f, A2 F21 = %.6f, difference %.2e (%.1f std errors)\n", lhs, rhs,
              lhs - rhs, std::abs(lhs - rhs) / se);
  EXPECT_LT(std::abs(lhs - rhs), 4.0 * se);
  // Nothing else in the scene: the rest escapes; one-sided discs facing each other: no back hits.
  EXPECT_NEAR(from1.toSpace.value, 1.0 - from1.toPatch[1].value, 1e-12);
  EXPECT_EQ(from1.toBackFace.value, 0.0);
  EXPECT_EQ(from1.toPatch[0].value, 0.0);  // a flat patch cannot see itself
}

TEST(ViewFactorCatalog, DirectlyOpposedRectangles) {
  const double a = 1.0, b = 2.0, c = 1.0;
  TriangleMesh m = makeRectangle("bottom", {0, 0, 0}, {a, 0, 0}, {0, b, 0});
  m.append(makeRectangle("top", {0, 0, c}, {0, b, 0}, {a, 0, 0}));  // normal -z
  const ViewFactorSolver solver(RadiationScene{m, {}, {}});
  const std::uint64_t rays = 1u << 20;
  const ReceiverResult r = solver.fromPatch("bottom", fixedRays(rays));
  expectCatalog("C-11 opposed rectangles 1 x 2 at 1", r.toPatch[1], opposedRectangles(a, b, c), r.rays);
}

TEST(ViewFactorCatalog, PerpendicularRectanglesWithCommonEdgeAndReciprocity) {
  // Common edge along y (length l), rectangle 1 in the floor (x in [0, w]), rectangle 2 in the
  // wall x = 0 (z in [0, h]).
  const double l = 1.0, w = 1.0, h = 2.0;
  TriangleMesh m = makeRectangle("floor", {0, 0, 0}, {w, 0, 0}, {0, l, 0});  // normal +z
  m.append(makeRectangle("wall", {0, 0, 0}, {0, l, 0}, {0, 0, h}));         // normal +x
  const ViewFactorSolver solver(RadiationScene{m, {}, {}});
  const std::uint64_t rays = 1u << 20;
  const ReceiverResult fromFloor = solver.fromPatch("floor", fixedRays(rays));
  const ReceiverResult fromWall = solver.fromPatch("wall", fixedRays(rays));
  expectCatalog("C-14 perpendicular l=1 w=1 h=2, floor->wall", fromFloor.toPatch[1],
                perpendicularRectangles(l, w, h), fromFloor.rays);
  expectCatalog("C-14 perpendicular, wall->floor", fromWall.toPatch[0], perpendicularRectangles(l, h, w),
                fromWall.rays);
  const double lhs = w * l * fromFloor.toPatch[1].value, rhs = h * l * fromWall.toPatch[0].value;
  const double se = std::hypot(w * l * fromFloor.toPatch[1].standardError, h * l * fromWall.toPatch[0].standardError);
  std::printf("  reciprocity A1 F12 = %.6f, A2 F21 = %.6f, difference %.2e (%.1f std errors)\n", lhs, rhs,
              lhs - rhs, std::abs(lhs - rhs) / se);
  EXPECT_LT(std::abs(lhs - rhs), 4.0 * se);
}

TEST(ViewFactorCatalog, DifferentialElementToSphereAndItsFlux) {
  // The sphere is an emitter (an exact sphere in Embree), at 2000 K with emissivity 0.8.
  const double R = 1.0, d = 3.0, T = 2000.0, eps = 0.8;
  RadiationScene scene;
  scene.emitters.add(0.0, 0.0, d, R, T, eps, "hot sphere");
  const ViewFactorSolver solver(scene);
  const std::uint64_t rays = 1u << 18;
  const ReceiverResult onAxis = solver.fromPoint({0, 0, 0}, {0, 0, 1}, fixedRays(rays));
  expectCatalog("D-16 element to sphere R=1 d=3", onAxis.toGroup[0], elementToSphere(R, d, 0.0), onAxis.rays);
  const double phi = 40.0 * kPi / 180.0;  // < acos(1/3) = 70.5 degrees
  const ReceiverResult tilted =
      solver.fromPoint({0, 0, 0}, {std::sin(phi), 0, std::cos(phi)}, fixedRays(rays));
  expectCatalog("D-18 element to sphere, normal tilted 40 deg", tilted.toGroup[0], elementToSphere(R, d, phi),
                tilted.rays);
  // q = eps sigma T^4 F: the flux is the same estimate scaled, so its relative error is F's.
  const double qExact = eps * kStefanBoltzmann * std::pow(T, 4) * elementToSphere(R, d, 0.0);
  std::printf("  flux from the sphere: exact %.1f W/m^2, MC %.1f +- %.1f\n", qExact, onAxis.flux.value,
              onAxis.flux.standardError);
  EXPECT_NEAR(onAxis.flux.value, qExact, kTolerance * qExact / elementToSphere(R, d, 0.0));
  EXPECT_NEAR(onAxis.fluxFromGroup[0].value, onAxis.flux.value, 1e-9 * qExact);
}

TEST(ViewFactorCatalog, DifferentialElementToCoaxialDisc) {
  const double r = 1.0, h = 1.0;
  const ViewFactorSolver solver(RadiationScene{makeDisc("disc", {0, 0, h}, {0, 0, -1}, r, kDiscSegments), {}, {}});
  const std::uint64_t rays = 1u << 18;
  const ReceiverResult onAxis = solver.fromPoint({0, 0, 0}, {0, 0, 1}, fixedRays(rays));
  expectCatalog("D-12 element to coaxial disc r=1 h=1", onAxis.toPatch[0], elementToDisc(r, h, 0.0), onAxis.rays);
  const double omega = 30.0 * kPi / 180.0;  // tan 30 = 0.58 < h / r
  const ReceiverResult tilted =
      solver.fromPoint({0, 0, 0}, {std::sin(omega), 0, std::cos(omega)}, fixedRays(rays));
  expectCatalog("B-13 element to disc, tilted 30 deg", tilted.toPatch[0], elementToDisc(r, h, omega),
                tilted.rays);
}

TEST(ViewFactorClosure, CubeEnclosureSumsToOne) {
  // Inside a closed 1 m cube every ray hits a wall: the factors from a wall sum to exactly 1
  // (no ray escapes through an edge or corner: Embree's watertight mode), the wall sees nothing of
  // itself, and the opposite and adjacent walls match C-11 and C-14.
  const ViewFactorSolver solver(RadiationScene{makeEnclosure({0, 0, 0}, {1, 1, 1}), {}, {}});
  const std::uint64_t rays = 1u << 20;
  const ReceiverResult r = solver.fromPatch("x-", fixedRays(rays));
  const TriangleMesh& m = solver.scene().surfaces;
  double sum = 0.0;
  for (const Estimate& e : r.toPatch) sum += e.value;
  std::printf("  cube from x-: sum of factors %.15f, escaped %g, back faces %g\n", sum, r.toSpace.value,
              r.toBackFace.value);
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_EQ(r.toSpace.value, 0.0);
  EXPECT_EQ(r.toBackFace.value, 0.0);
  EXPECT_EQ(r.toPatch[static_cast<std::size_t>(m.findPatch("x-"))].value, 0.0);
  expectCatalog("cube: x- to x+ (C-11)", r.toPatch[static_cast<std::size_t>(m.findPatch("x+"))],
                opposedRectangles(1, 1, 1), r.rays);
  for (const char* wall : {"y-", "y+", "z-", "z+"})
    expectCatalog((std::string("cube: x- to ") + wall + " (C-14)").c_str(),
                  r.toPatch[static_cast<std::size_t>(m.findPatch(wall))], perpendicularRectangles(1, 1, 1), r.rays);
}

TEST(ViewFactorClosure, InsideASphereEveryRayReturnsToTheSphere) {
  // A tessellated sphere seen from inside: a concave patch sees itself, F_ii = 1, from its surface
  // and from its centre in all directions.
  TriangleMesh sphere = makeSphere("shell", {0.3, -0.2, 0.1}, 2.0, 3);
  sphere.flip();
  const ViewFactorSolver solver(RadiationScene{sphere, {}, {}});
  const ReceiverResult fromShell = solver.fromPatch("shell", fixedRays(1u << 18));
  EXPECT_EQ(fromShell.toPatch[0].value, 1.0);
  EXPECT_EQ(fromShell.toPatch[0].standardError, 0.0);
  const ReceiverResult fromCentre = solver.allDirectionsFrom({0.3, -0.2, 0.1}, fixedRays(1u << 16));
  EXPECT_EQ(fromCentre.toPatch[0].value, 1.0);
  EXPECT_EQ(fromCentre.toBackFace.value, 0.0);
}

TEST(ViewFactorSolidAngle, SphereSeenFromAPoint) {
  // Solid angle of a sphere of radius R at distance d: 2 pi (1 - sqrt(1 - (R/d)^2)).
  const double R = 0.5, d = 2.0;
  RadiationScene scene;
  scene.emitters.add(d, 0.0, 0.0, R, 1600.0, 0.45, "particle");
  const ViewFactorSolver solver(scene);
  const Estimate omega = solver.emitterSolidAngle({0, 0, 0}, fixedRays(1u << 18));
  const double exact = 2.0 * kPi * (1.0 - std::sqrt(1.0 - (R / d) * (R / d)));
  std::printf("  solid angle of a sphere R=0.5 d=2: exact %.6f sr, MC %.6f +- %.1e\n", exact, omega.value,
              omega.standardError);
  EXPECT_NEAR(omega.value, exact, 4.0 * kTolerance);  // 4 pi x the 1e-3 fraction tolerance
  EXPECT_LE(omega.standardError, 4.0 * kPi * kMaxStandardError);
}

TEST(ViewFactorErrorEstimate, StandardErrorIsHonest) {
  // Many independent estimates (different seeds) of two catalog factors at a modest ray count:
  // the standardised error z = (estimate - exact) / standard error should behave like a Student
  // t variable with replicates - 1 = 15 degrees of freedom: |z| <= 2 in about 94% of runs,
  // E[z^2] = 15/13 = 1.15. An error estimate 2x too small would give E[z^2] ~ 4.6, 2x too large
  // ~0.29; the bounds below sit between, with room for the sampling spread of 48 runs.
  const double r1 = 0.5, r2 = 1.0, h = 1.0;
  RadiationScene discs{twoDiscs(r1, r2, h), {}, {}};
  const ViewFactorSolver discSolver(discs);
  RadiationScene sphereScene;
  sphereScene.emitters.add(0.0, 0.0, 3.0, 1.0, 2000.0, 1.0, "sphere");
  const ViewFactorSolver sphereSolver(sphereScene);
  for (const sampling::Sampler sampler : {sampling::Sampler::Sobol, sampling::Sampler::Random}) {
    const char* label = sampler == sampling::Sampler::Sobol ? "Sobol" : "random";
    int within2 = 0, runs = 0;
    double sumZ2 = 0.0, sumSe = 0.0;
    for (std::uint64_t seed = 1; seed <= 24; ++seed) {
      SamplingOptions o = fixedRays(16 * 1024, seed);
      o.sampler = sampler;
      const Estimate a = discSolver.fromPatch("disc1", o).toPatch[1];
      const Estimate b = sphereSolver.fromPoint({0, 0, 0}, {0, 0, 1}, o).toGroup[0];
      for (const auto& [e, exact] : {std::pair{a, coaxialDiscs(r1, r2, h)}, std::pair{b, elementToSphere(1.0, 3.0, 0.0)}}) {
        ASSERT_GT(e.standardError, 0.0);
        const double z = (e.value - exact) / e.standardError;
        within2 += std::abs(z) <= 2.0 ? 1 : 0;
        sumZ2 += z * z;
        sumSe += e.standardError;
        ++runs;
      }
    }
    const double meanZ2 = sumZ2 / runs, fraction = static_cast<double>(within2) / runs;
    std::printf("  %s: %d runs of 16384 rays, mean std error %.2e, |z| <= 2 in %.0f%%, mean z^2 %.2f\n", label,
                runs, sumSe / runs, 100.0 * fraction, meanZ2);
    EXPECT_GE(fraction, 0.8) << label;
    EXPECT_GT(meanZ2, 0.45) << label;
    EXPECT_LT(meanZ2, 2.5) << label;
  }
}

TEST(ViewFactorAdaptive, StopsAtTheRequestedTolerance) {
  const ViewFactorSolver solver(RadiationScene{twoDiscs(0.5, 1.0, 1.0), {}, {}});
  SamplingOptions o;
  o.absoluteTolerance = 4e-4;
  o.minRays = 1u << 14;
  o.sampler = sampling::Sampler::Random;  // error ~ 1/sqrt(N): several doublings needed
  const ReceiverResult r = solver.fromPatch("disc1", o);
  std::printf("  adaptive (random points), tolerance 4e-4: %llu rays, F12 = %.5f +- %.1e\n",
              static_cast<unsigned long long>(r.rays), r.toPatch[1].value, r.toPatch[1].standardError);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.toPatch[1].standardError, o.absoluteTolerance);
  EXPECT_GT(r.rays, o.minRays);  // it had to extend
  EXPECT_NEAR(r.toPatch[1].value, coaxialDiscs(0.5, 1.0, 1.0), 4.0 * o.absoluteTolerance);
  // A cap it cannot meet: stops at maxRays and says so.
  o.absoluteTolerance = 1e-6;
  o.maxRays = 1u << 16;
  const ReceiverResult capped = solver.fromPatch("disc1", o);
  EXPECT_FALSE(capped.converged);
  EXPECT_LE(capped.rays, o.maxRays);
}

}  // namespace
}  // namespace ejecta::radiation
