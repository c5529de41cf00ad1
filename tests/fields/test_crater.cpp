// Crater analysis on analytic targets with a smeared surface, as an SPH estimate gives: depth,
// apparent and rim diameters, volume, mass, elongation, planar runs, gap bridging, detached
// ejecta, the no-crater case, option errors, thread independence and the profile CSV.
#include <gtest/gtest.h>
#ifdef _OPENMP
#include <omp.h>  // the OpenMP runtime, which crater.cpp uses: thread-count test only
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fields/crater.hpp"

namespace ejecta::fields {
namespace {

constexpr double kPi = std::numbers::pi;

// Filled fraction for a signed distance sd to the target's surface (positive outside): 1 inside,
// 0 outside, a linear ramp over a width w about the surface, as an SPH estimate smears it over
// about one resolution.
double smeared(double sd, double w) { return std::clamp(0.5 - sd / w, 0.0, 1.0); }

double length(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); }

// Half-space y < 0 with a hemispherical hole of radius a centred at (cx, 0, cz).
double halfSpaceWithHole(const Point& p, double a, double cx, double cz) {
  return std::max(p[1], a - length(p[0] - cx, p[1], p[2] - cz));
}

CraterOptions planeOptions(double resolution) {
  CraterOptions o;
  o.surface.kind = ReferenceSurface::Kind::Plane;
  o.surface.point = {0.0, 0.0, 0.0};
  o.surface.normal = {0.0, 1.0, 0.0};
  o.resolution = resolution;
  // Analytic fields meet the original level exactly: measure the apparent rim at zero depth,
  // not at the tolerance that absorbs an SPH surface's rounded edge.
  o.levelTolerance = 1e-6 * o.resolution;
  return o;
}

// Hemispherical hole in a half-space: the reference case with an exact depth, diameter and
// volume.
TEST(Crater, HemisphericalHoleInAHalfSpace) {
  const double a = 4.93, h = 0.1, cx = 1.0, cz = -2.0;  // a: not on a bin edge
  CraterOptions o = planeOptions(h);
  o.surface.point = {7.0, 0.0, 3.0};        // any point of the plane
  o.impactPoint = {cx, 0.7, cz};            // projected onto the plane: the hole's centre
  o.targetDensity = 2000.0;
  const auto field = [&](const Point& p) { return smeared(halfSpaceWithHole(p, a, cx, cz), h); };
  const CraterMetrics m = analyseCrater(field, o);

  ASSERT_TRUE(m.found) << m.note;
  EXPECT_TRUE(m.note.empty()) << m.note;
  // The deepest samples are in the first bin, rho = h/2 off the axis, h^2/(8a) = 2.5e-4 m above
  // the bottom. There the depth is exact but for the linear interpolation along the ray of the
  // smeared ramp, whose curvature is 1/a. Measured: 6e-9 m. Bound: 1e-6 m.
  const double firstBin = std::sqrt(a * a - 0.25 * h * h);
  EXPECT_NEAR(m.depth, firstBin, 1e-6);
  EXPECT_NEAR(m.deepestPoint[1], -firstBin, 1e-6);
  EXPECT_NEAR(std::hypot(m.deepestPoint[0] - cx, m.deepestPoint[2] - cz), 0.5 * h, 1e-9);
  // The wall meets the original surface vertically. The bisection leaves a bracket of h/256 =
  // 3.9e-4 m per side, i.e. 7.8e-4 m on a diameter. Measured: 1.6e-4 m on the diameter, 7.8e-5 m
  // on every radius. Bounds: h/100 on the diameter, h/200 on the radii.
  EXPECT_NEAR(m.apparentDiameter, 2.0 * a, 0.01 * h);
  ASSERT_EQ(m.apparentRadius.size(), 72u);
  for (double r : m.apparentRadius) EXPECT_NEAR(r, a, 0.005 * h);
  // Midpoint rule over 50 bins of an integrand with a square-root edge: measured 0.09% low.
  // Bound: 0.2%.
  const double exact = 2.0 / 3.0 * kPi * a * a * a;
  EXPECT_NEAR(m.volume, exact, 0.002 * exact);
  EXPECT_DOUBLE_EQ(m.excavatedMass, 2000.0 * m.volume);
  // No rim: the surface outside is flat to round-off, and the crest is then put at the apparent
  // radius. Measured: both exact.
  EXPECT_NEAR(m.rimHeight, 0.0, 1e-9);
  EXPECT_NEAR(m.rimDiameter, m.apparentDiameter, 1e-9);
  // Circular: every pair has the same diameter, to the accuracy of the radii. Measured: exact.
  EXPECT_NEAR(m.elongation, 1.0, 1e-3);
  // Profile: 60 bins of h (the default search radius), mean depth sqrt(a^2 - rho^2).
  ASSERT_EQ(m.profile.size(), 60u);
  for (const CraterProfileBin& b : m.profile) {
    const double expected = b.distance < a ? std::sqrt(a * a - b.distance * b.distance) : 0.0;
    // Linear interpolation along the ray of a ramp curved by the hole: measured <= 3.0e-4 m, the
    // largest in the last bin inside the steep wall. Bound 5e-4.
    EXPECT_NEAR(b.depthMean, expected, 5e-4) << "rho " << b.distance;
    EXPECT_LE(b.depthMin, b.depthMean + 1e-12);  // the mean of equal values: round-off
    EXPECT_GE(b.depthMax, b.depthMean - 1e-12);
  }
}

// Sphere (R = 35 m, off the origin, tilted axis) with a paraboloidal bowl: apex d below the axis
// point, z = -d + d q^2 / rc^2 in the axis frame (q: distance from the axis).
struct SphereBowl {
  Point center{10.0, -35.0, 5.0};
  double R = 35.0, d = 4.0, rc = 6.0, w = 0.1;
  Point n{};  // axis
  SphereBowl() {
    const double l = length(1.0, 2.0, 0.5);
    n = {1.0 / l, 2.0 / l, 0.5 / l};
  }
  Point impact() const {
    return {center[0] + 50.0 * n[0], center[1] + 50.0 * n[1], center[2] + 50.0 * n[2]};
  }
  double operator()(const Point& p) const {
    const double x = p[0] - center[0], y = p[1] - center[1], z0 = p[2] - center[2];
    const double sphere = length(x, y, z0) - R;
    const double z = x * n[0] + y * n[1] + z0 * n[2] - R;  // height above the axis point
    const double q = std::sqrt(std::max(0.0, length(x, y, z0) * length(x, y, z0) -
                                                 (z + R) * (z + R)));
    // Vertical distance into the bowl, over its gradient: a first-order signed distance.
    const double bowl = (z + d - d * q * q / (rc * rc)) / std::hypot(1.0, 2.0 * d * q / (rc * rc));
    return smeared(std::max(sphere, bowl), w);
  }
  // Where the bowl meets the sphere, as a distance from the axis: sqrt(R^2-q^2) - R = z_p(q).
  double qEdge() const {
    double lo = 0.0, hi = rc;
    for (int i = 0; i < 200; ++i) {
      const double q = 0.5 * (lo + hi);
      const double gap = std::sqrt(R * R - q * q) - R - (-d + d * q * q / (rc * rc));
      (gap > 0.0 ? lo : hi) = q;
    }
    return 0.5 * (lo + hi);
  }
  // The bowl's volume inside the sphere: 2 pi int_0^q* q (z_sphere - z_bowl) dq, in closed form.
  double volume() const {
    const double q = qEdge(), q2 = q * q;
    return 2.0 * kPi *
           ((R * R * R - std::pow(R * R - q2, 1.5)) / 3.0 - 0.5 * R * q2 + 0.5 * d * q2 -
            0.25 * d * q2 * q2 / (rc * rc));
  }
};

CraterOptions sphereOptions(const SphereBowl& bowl) {
  CraterOptions o;
  o.surface.kind = ReferenceSurface::Kind::Sphere;
  o.surface.center = bowl.center;
  o.surface.radius = bowl.R;
  o.impactPoint = bowl.impact();
  o.resolution = bowl.w;
  // Analytic fields meet the original level exactly: measure the apparent rim at zero depth,
  // not at the tolerance that absorbs an SPH surface's rounded edge.
  o.levelTolerance = 1e-6 * o.resolution;
  o.searchRadius = 9.0;
  return o;
}

TEST(Crater, ParaboloidalBowlOnASphere) {
  const SphereBowl bowl;
  CraterOptions o = sphereOptions(bowl);
  o.targetDensity = 2650.0;
  const CraterMetrics m = analyseCrater(std::cref(bowl), o);
  ASSERT_TRUE(m.found) << m.note;
  EXPECT_TRUE(m.note.empty()) << m.note;
  // The deepest samples are in the first bin, h/2 off the axis, about d (h/2)^2 / rc^2 = 2.8e-4 m
  // above the apex: the ray at theta = h/(2R) meets the bowl at the smaller root s of
  // (d sin^2/rc^2) s^2 - cos s + (R - d) = 0. Measured: 4e-11 m. Bound: 1e-6 m.
  const double theta = 0.5 * bowl.w / bowl.R;
  const double qa = bowl.d * std::sin(theta) * std::sin(theta) / (bowl.rc * bowl.rc);
  const double qb = std::cos(theta), qc = bowl.R - bowl.d;
  const double s = 2.0 * qc / (qb + std::sqrt(qb * qb - 4.0 * qa * qc));
  EXPECT_NEAR(m.depth, bowl.R - s, 1e-6);
  // The bowl meets the sphere at arc distance R asin(q*/R) from the axis.
  const double diameter = 2.0 * bowl.R * std::asin(bowl.qEdge() / bowl.R);
  // The bisection leaves h/256 per side (7.8e-4 m on the diameter). Measured: 3.0e-4 m.
  // Bound: h/100.
  EXPECT_NEAR(m.apparentDiameter, diameter, 0.01 * bowl.w);
  // Midpoint rule on 0.1 m bins of a smooth integrand: measured 0.004%. Bound: 0.01%.
  EXPECT_NEAR(m.volume, bowl.volume(), 1e-4 * bowl.volume());
  EXPECT_DOUBLE_EQ(m.excavatedMass, 2650.0 * m.volume);
  EXPECT_NEAR(m.elongation, 1.0, 1e-3);  // to the radii's accuracy; measured exact
  // The deepest point lies on the axis, d below the original surface.
  const Point p = m.deepestPoint;
  const double r = length(p[0] - bowl.center[0], p[1] - bowl.center[1], p[2] - bowl.center[2]);
  EXPECT_NEAR(r, bowl.R - m.depth, 1e-9);
  // Profile bins are 0.1 m wide out to the 9 m search radius.
  EXPECT_EQ(m.profile.size(), 90u);
}

// A plane with a tilted normal, a paraboloidal bowl and a raised rim: an annular cos^2 bump of
// height H whose foot is the bowl's edge and whose crest is at rc + hw.
TEST(Crater, RaisedRim) {
  const double d = 2.0, rc = 3.97, H = 0.8, hw = 1.52, h = 0.1;
  const double crestRadius = rc + hw;
  const double ln = length(0.3, 1.0, -0.2);
  const Point n{0.3 / ln, 1.0 / ln, -0.2 / ln};
  const Point origin{2.0, 1.0, -3.0};
  auto surface = [&](double q) -> std::array<double, 2> {  // present height and its slope
    if (q < rc) return {-d * (1.0 - q * q / (rc * rc)), 2.0 * d * q / (rc * rc)};
    if (q < rc + 2.0 * hw) {
      const double phase = 0.5 * kPi * (q - crestRadius) / hw;
      return {H * std::cos(phase) * std::cos(phase), -H * std::sin(2.0 * phase) * 0.5 * kPi / hw};
    }
    return {0.0, 0.0};
  };
  const auto field = [&](const Point& p) {
    const Point r{p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]};
    const double z = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
    const double q = std::sqrt(std::max(0.0, r[0] * r[0] + r[1] * r[1] + r[2] * r[2] - z * z));
    const auto [height, slope] = surface(q);
    return smeared((z - height) / std::hypot(1.0, slope), h);
  };
  CraterOptions o = planeOptions(h);
  o.surface.point = {origin[0] + 3.0 * n[1], origin[1] - 3.0 * n[0], origin[2]};  // on the plane
  o.surface.normal = {3.0 * n[0], 3.0 * n[1], 3.0 * n[2]};  // not unit: normalised
  o.impactPoint = origin;
  o.searchRadius = 9.0;  // the rim search needs 2 rc = 8 m
  const CraterMetrics m = analyseCrater(field, o);
  ASSERT_TRUE(m.found) << m.note;
  // First bin, h/2 off the axis: d (1 - h^2 / (4 rc^2)); the field's ramp is linear along the
  // ray, so the interpolation is exact. Measured: 2e-16 m. Bound: 1e-9 m.
  EXPECT_NEAR(m.depth, d * (1.0 - 0.25 * h * h / (rc * rc)), 1e-9);
  // The bump rises from the bowl's edge, so the surface returns to the original level at rc.
  // Bisection: h/256 per side. Measured 6.2e-4 m on the diameter. Bound h/100.
  EXPECT_NEAR(m.apparentDiameter, 2.0 * rc, 0.01 * h);
  // The crest is refined by a parabola through the highest bin and its neighbours: measured
  // 1.0e-4 m on the diameter and 1.2e-5 m on the height (the parabola against the cos^2 peak).
  // Bounds: 3e-4 m and 3e-5 m.
  EXPECT_NEAR(m.rimDiameter, 2.0 * crestRadius, 3e-4);
  EXPECT_NEAR(m.rimHeight, H, 3e-5);
  // Bowl volume pi d rc^2 / 2 (the bump is above the original surface and is not counted).
  // Midpoint rule: measured 0.009%. Bound 0.02%.
  const double exact = 0.5 * kPi * d * rc * rc;
  EXPECT_NEAR(m.volume, exact, 2e-4 * exact);
  // The whole profile follows the surface: along each ray the field is a linear ramp (vertical
  // distance over a slope that is constant on the ray), so the crossings are exact. Measured:
  // 3e-15 m. Bound: 1e-12 m.
  for (const CraterProfileBin& b : m.profile) {
    EXPECT_NEAR(-b.depthMean, surface(b.distance)[0], 1e-12) << "rho " << b.distance;
  }
}

// Elliptic hole (semi-axes a along u, b across, depth c) whose long axis is 30 degrees from x in
// the x-z plane of a half-space y < 0.
struct EllipticHole {
  double a = 4.03, b = 2.47, c = 2.0, w = 0.1, alpha = kPi / 6.0;
  double operator()(const Point& p) const {
    const double u = p[0] * std::cos(alpha) + p[2] * std::sin(alpha);
    const double v = -p[0] * std::sin(alpha) + p[2] * std::cos(alpha);
    const double e = 1.0 - u * u / (a * a) - v * v / (b * b);
    const double height = e > 0.0 ? -c * std::sqrt(e) : 0.0;
    return smeared(p[1] - height, w);
  }
};

TEST(Crater, ElongatedHoleWithTheTrackGiven) {
  const EllipticHole hole;
  CraterOptions o = planeOptions(hole.w);
  // The track dives into the target: only its part along the surface matters.
  o.alongTrack = {std::cos(hole.alpha), -0.8, std::sin(hole.alpha)};
  const CraterMetrics m = analyseCrater(std::cref(hole), o);
  ASSERT_TRUE(m.found) << m.note;
  // First bin, h/2 off the axis along the long axis (a sector lies on it); the ramp is linear
  // along the rays. Measured: exact. Bound: 1e-9 m.
  const double h = hole.w;
  EXPECT_NEAR(m.depth, hole.c * std::sqrt(1.0 - 0.25 * h * h / (hole.a * hole.a)), 1e-9);
  // The sectors are aligned with the track, so along and across are sampled exactly; the walls
  // are vertical at the edge and the bisection ends within h/256 per side. Measured: 1.6e-4 m
  // along, 6.3e-4 m across, 1.8e-4 on the elongation. Bounds: h/100, 5e-4.
  EXPECT_NEAR(m.alongTrackDiameter, 2.0 * hole.a, 0.01 * hole.w);
  EXPECT_NEAR(m.crossTrackDiameter, 2.0 * hole.b, 0.01 * hole.w);
  EXPECT_NEAR(m.elongation, hole.a / hole.b, 5e-4);
  // The mean over all pairs lies between the two (the ellipse's mean diameter).
  EXPECT_GT(m.apparentDiameter, 2.0 * hole.b);
  EXPECT_LT(m.apparentDiameter, 2.0 * hole.a);
  // Volume of a half ellipsoid: 2/3 pi a b c. Midpoint rule with a square-root edge: measured
  // 0.06%. Bound 0.1%.
  const double exact = 2.0 / 3.0 * kPi * hole.a * hole.b * hole.c;
  EXPECT_NEAR(m.volume, exact, 1e-3 * exact);
}

TEST(Crater, ElongatedHoleWithoutTheTrack) {
  const EllipticHole hole;
  CraterOptions o = planeOptions(hole.w);
  const CraterMetrics m = analyseCrater(std::cref(hole), o);
  ASSERT_TRUE(m.found) << m.note;
  // The 72 sectors are 5 degrees apart and the default frame starts on x, so one pair lies on
  // the long axis (30 degrees) and one on the short one: the same bounds as with the track.
  EXPECT_NEAR(m.alongTrackDiameter, 2.0 * hole.a, 0.01 * hole.w);
  EXPECT_NEAR(m.crossTrackDiameter, 2.0 * hole.b, 0.01 * hole.w);
  EXPECT_NEAR(m.elongation, hole.a / hole.b, 5e-4);
  // A track along the axis (a vertical impact) gives the same answer, with a note.
  o.alongTrack = {0.0, -3.0, 0.0};
  const CraterMetrics vertical = analyseCrater(std::cref(hole), o);
  EXPECT_EQ(vertical.alongTrackDiameter, m.alongTrackDiameter);
  EXPECT_NE(vertical.note.find("alongTrack"), std::string::npos);
}

// Planar runs: a half-disc hole in a half-plane (the field does not depend on z) and a circular
// hole in a disc target. Volumes are areas per metre.
TEST(Crater, PlanarHalfDiscInAHalfPlane) {
  const double a = 4.93, h = 0.1;
  CraterOptions o = planeOptions(h);
  o.planar = true;
  o.azimuths = 1;  // ignored in planar runs
  o.impactPoint = {0.0, 0.3, 4.0};  // z is dropped
  o.targetDensity = 1000.0;
  const auto field = [&](const Point& p) {
    EXPECT_EQ(p[2], 0.0);  // planar runs sample z = 0 only
    return smeared(std::max(p[1], a - std::hypot(p[0], p[1])), h);
  };
  const CraterMetrics m = analyseCrater(field, o);
  ASSERT_TRUE(m.found) << m.note;
  EXPECT_NEAR(m.depth, std::sqrt(a * a - 0.25 * h * h), 1e-6);  // as in 3D
  ASSERT_EQ(m.apparentRadius.size(), 2u);
  EXPECT_NEAR(m.apparentDiameter, 2.0 * a, 0.01 * h);  // as in 3D: measured 1.6e-4 m
  EXPECT_EQ(m.alongTrackDiameter, m.apparentDiameter);
  EXPECT_EQ(m.crossTrackDiameter, m.apparentDiameter);
  EXPECT_EQ(m.elongation, 1.0);
  // Area pi a^2 / 2 by the midpoint rule on 0.1 m bins: measured 0.04% low. Bound 0.1%.
  const double exact = 0.5 * kPi * a * a;
  EXPECT_NEAR(m.volume, exact, 1e-3 * exact);
  EXPECT_DOUBLE_EQ(m.excavatedMass, 1000.0 * m.volume);
  EXPECT_EQ(m.deepestPoint[2], 0.0);
}

// A circular hole of radius a centred c above the surface of a disc of radius R: its bottom is
// a - c deep. (A hole centred on or below the surface would undercut it as seen along the rays
// from the centre, an overhang: see docs/crater.md.)
TEST(Crater, PlanarCircularHoleInADisc) {
  const double R = 35.0, a = 8.0, c = 3.0, h = 0.1;
  const double D = R + c;  // distance between the centres
  CraterOptions o;
  o.planar = true;
  o.surface.kind = ReferenceSurface::Kind::Sphere;
  o.surface.center = {0.0, 0.0, 0.0};
  o.surface.radius = R;
  o.impactPoint = {0.0, 20.0, 0.0};
  o.resolution = h;
  // Analytic fields meet the original level exactly: measure the apparent rim at zero depth,
  // not at the tolerance that absorbs an SPH surface's rounded edge.
  o.levelTolerance = 1e-6 * o.resolution;
  o.searchRadius = 10.0;  // the crater is 14 m wide
  const auto field = [&](const Point& p) {
    return smeared(std::max(std::hypot(p[0], p[1]) - R, a - std::hypot(p[0], p[1] - D)), h);
  };
  const CraterMetrics m = analyseCrater(field, o);
  ASSERT_TRUE(m.found) << m.note;
  // First bin: the ray at theta0 = h/(2R) meets the hole's circle at D cos - sqrt(a^2 - D^2 sin^2).
  // Measured: 2e-11 m. Bound: 1e-6 m.
  const double theta0 = 0.5 * h / R;
  const double s0 = D * std::cos(theta0) -
                    std::sqrt(a * a - D * D * std::sin(theta0) * std::sin(theta0));
  EXPECT_NEAR(m.depth, R - s0, 1e-6);
  // The circles cross at angle theta from the axis (law of cosines); the diameter is the arc
  // 2 R theta. Measured 6.4e-4 m. Bound h/100 (the bisection leaves h/256 per side).
  const double theta = std::acos((R * R + D * D - a * a) / (2.0 * R * D));
  EXPECT_NEAR(m.apparentDiameter, 2.0 * R * theta, 0.01 * h);
  // The lens shared by the disc and the hole.
  const double lens = R * R * theta + a * a * std::acos((D * D + a * a - R * R) / (2.0 * D * a)) -
                      0.5 * std::sqrt((-D + R + a) * (D + R - a) * (D - R + a) * (D + R + a));
  EXPECT_NEAR(m.volume, lens, 3e-5 * lens);  // midpoint rule: measured 0.001%. Bound 0.003%
}

// A void crack shorter than gapBridge under the crater floor is bridged; a longer one is taken as
// the surface. Detached material above the floor (ejecta) is not the surface.
TEST(Crater, BridgesShortVoidsAndIgnoresDetachedEjecta) {
  const double a = 5.0, h = 0.1;
  const CraterOptions o = planeOptions(h);
  const auto hole = [&](const Point& p) { return halfSpaceWithHole(p, a, 0.0, 0.0); };
  const CraterMetrics plain = analyseCrater([&](const Point& p) { return smeared(hole(p), h); }, o);
  ASSERT_TRUE(plain.found);

  // A horizontal crack 0.1 m thick (half the default bridge of 2 h) 0.6 m under the floor.
  const auto cracked = [&](const Point& p) {
    return smeared(std::max(hole(p), 0.05 - std::abs(p[1] + 5.6)), h);
  };
  const CraterMetrics bridged = analyseCrater(cracked, o);
  ASSERT_TRUE(bridged.found);
  // The rays' samples differ only in the crack, which is bridged: every crossing is found from
  // the same samples as without the crack, so the results are identical.
  EXPECT_EQ(bridged.depth, plain.depth);
  EXPECT_EQ(bridged.apparentDiameter, plain.apparentDiameter);
  EXPECT_EQ(bridged.volume, plain.volume);
  EXPECT_EQ(bridged.profile.back().depthMean, plain.profile.back().depthMean);

  // A bridge shorter than the crack: the crack's lower face (5.65 m deep) is the surface, under
  // the crater and around it, so the surface never returns to the original level.
  CraterOptions narrow = o;
  narrow.gapBridge = 0.05;
  const CraterMetrics broken = analyseCrater(cracked, narrow);
  EXPECT_NEAR(broken.depth, 5.65, 1e-9);  // a linear ramp across a flat face: exact
  EXPECT_NE(broken.note.find("does not return"), std::string::npos) << broken.note;

  // Ejecta: a 1 m ball of material floating inside the crater, and one above the surface.
  const auto ejecta = [&](const Point& p) {
    const double inside = length(p[0] - 0.5, p[1] + 2.5, p[2]) - 1.0;
    const double above = length(p[0], p[1] - 2.5, p[2] + 1.0) - 1.0;
    return smeared(std::min({hole(p), inside, above}), h);
  };
  const CraterMetrics withEjecta = analyseCrater(ejecta, o);
  ASSERT_TRUE(withEjecta.found);
  // Every ray stops once it has seen more than gapBridge of void above the floor, before it
  // reaches the balls: identical results.
  EXPECT_EQ(withEjecta.depth, plain.depth);
  EXPECT_EQ(withEjecta.apparentDiameter, plain.apparentDiameter);
  EXPECT_EQ(withEjecta.volume, plain.volume);
  EXPECT_TRUE(withEjecta.note.empty()) << withEjecta.note;
}

TEST(Crater, NoCrater) {
  const double h = 0.1;
  const CraterOptions o = planeOptions(h);
  // Flat, and then a dent half a resolution deep: both below the one-resolution threshold.
  const CraterMetrics flat = analyseCrater([&](const Point& p) { return smeared(p[1], h); }, o);
  EXPECT_FALSE(flat.found);
  EXPECT_NE(flat.note.find("no crater"), std::string::npos) << flat.note;
  EXPECT_EQ(flat.depth, 0.0);
  EXPECT_EQ(flat.apparentDiameter, 0.0);
  EXPECT_EQ(flat.volume, 0.0);
  EXPECT_EQ(flat.profile.size(), 60u);  // the measured (flat) profile is still given
  const CraterMetrics dent = analyseCrater(
      [&](const Point& p) {
        const double q2 = (p[0] * p[0] + p[2] * p[2]) / 4.0;  // 2 m wide paraboloid
        return smeared(p[1] + 0.05 * std::max(0.0, 1.0 - q2), h);
      },
      o);
  EXPECT_FALSE(dent.found);
  EXPECT_FALSE(dent.note.empty());
  // A target missing altogether (all void): no crater, and the note says the rays started in
  // void.
  const CraterMetrics none = analyseCrater([](const Point&) { return 0.0; }, o);
  EXPECT_FALSE(none.found);
  EXPECT_NE(none.note.find("void at their start"), std::string::npos) << none.note;
}

// Rays start one search radius below the original surface: a crater deeper than that is cut
// off there, and the note says the depth is a lower bound.
TEST(Crater, CraterDeeperThanTheRayStart) {
  const double a = 5.0, h = 0.1;
  CraterOptions o = planeOptions(h);
  o.searchRadius = 4.0;
  const CraterMetrics m = analyseCrater(
      [&](const Point& p) { return smeared(halfSpaceWithHole(p, a, 0.0, 0.0), h); }, o);
  ASSERT_TRUE(m.found);
  EXPECT_EQ(m.depth, 4.0);  // the start of the rays, exactly
  EXPECT_NE(m.note.find("lower bound"), std::string::npos) << m.note;
  EXPECT_NE(m.note.find("does not return"), std::string::npos) << m.note;
  EXPECT_EQ(m.apparentDiameter, 8.0);  // the search radius on every side
}

void expectInvalid(const CraterOptions& o, const std::string& option) {
  const auto field = [](const Point& p) { return smeared(p[1], 0.1); };
  try {
    analyseCrater(field, o);
    ADD_FAILURE() << "no exception for option " << option;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'" + option + "'"), std::string::npos) << e.what();
  }
}

TEST(Crater, RejectsBadOptions) {
  const CraterOptions good = planeOptions(0.1);
  CraterOptions o = good;
  o.resolution = 0.0;
  expectInvalid(o, "resolution");
  o.resolution = -1.0;
  expectInvalid(o, "resolution");
  o = good;
  o.surface.normal = {0.0, 0.0, 0.0};
  expectInvalid(o, "surface.normal");
  o = good;
  o.planar = true;
  o.surface.normal = {0.0, 0.0, 1.0};  // no part in the x-y plane
  expectInvalid(o, "surface.normal");
  o = good;
  o.azimuths = 3;
  expectInvalid(o, "azimuths");
  o = good;
  o.levelTolerance = -0.01;
  expectInvalid(o, "levelTolerance");
  for (double t : {0.0, 1.0, 1.5, -0.2}) {
    o = good;
    o.threshold = t;
    expectInvalid(o, "threshold");
  }
  o = good;
  o.searchRadius = -1.0;
  expectInvalid(o, "searchRadius");
  o = good;
  o.searchRadius = 1e6;  // 1e7 bins of 0.1 m
  expectInvalid(o, "searchRadius");
  o = good;
  o.gapBridge = -0.1;
  expectInvalid(o, "gapBridge");
  o = good;
  o.targetDensity = -1.0;
  expectInvalid(o, "targetDensity");
  o = good;
  o.surface.kind = ReferenceSurface::Kind::Sphere;
  o.surface.radius = 0.0;
  o.impactPoint = {0.0, 1.0, 0.0};
  expectInvalid(o, "surface.radius");
  o.surface.radius = 10.0;
  o.surface.center = o.impactPoint;
  expectInvalid(o, "impactPoint");
  // The message names the option and the offending value.
  o = good;
  o.resolution = 0.0;
  try {
    analyseCrater([](const Point&) { return 1.0; }, o);
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "crater: option 'resolution' must be positive (got 0)");
  }
}

TEST(Crater, SameResultForAnyThreadCount) {
#ifdef _OPENMP
  const SphereBowl bowl;
  const CraterOptions o = sphereOptions(bowl);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const CraterMetrics one = analyseCrater(std::cref(bowl), o);
  omp_set_num_threads(2);
  const CraterMetrics two = analyseCrater(std::cref(bowl), o);
  omp_set_num_threads(threads);
  // Every ray writes its own slot and the sums run serially: bit-for-bit equality.
  EXPECT_EQ(one.found, two.found);
  EXPECT_EQ(one.note, two.note);
  EXPECT_EQ(one.depth, two.depth);
  EXPECT_EQ(one.deepestPoint, two.deepestPoint);
  EXPECT_EQ(one.apparentDiameter, two.apparentDiameter);
  EXPECT_EQ(one.rimDiameter, two.rimDiameter);
  EXPECT_EQ(one.rimHeight, two.rimHeight);
  EXPECT_EQ(one.volume, two.volume);
  EXPECT_EQ(one.alongTrackDiameter, two.alongTrackDiameter);
  EXPECT_EQ(one.crossTrackDiameter, two.crossTrackDiameter);
  EXPECT_EQ(one.elongation, two.elongation);
  EXPECT_EQ(one.apparentRadius, two.apparentRadius);
  EXPECT_EQ(craterProfileCsv(one), craterProfileCsv(two));
#else
  GTEST_SKIP() << "built without OpenMP";
#endif
}

TEST(Crater, ProfileCsv) {
  const double a = 2.0, h = 0.1;
  CraterOptions o = planeOptions(h);
  o.searchRadius = 3.0;
  const CraterMetrics m =
      analyseCrater([&](const Point& p) { return smeared(halfSpaceWithHole(p, a, 0, 0), h); }, o);
  ASSERT_EQ(m.profile.size(), 30u);
  std::istringstream csv(craterProfileCsv(m));
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "distance_m,depth_mean_m,depth_min_m,depth_max_m");
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    const CraterProfileBin& b = m.profile.at(rows);
    double distance = 0, mean = 0, lo = 0, hi = 0;
    char c1 = 0, c2 = 0, c3 = 0;
    std::istringstream row(line);
    row >> distance >> c1 >> mean >> c2 >> lo >> c3 >> hi;
    ASSERT_FALSE(row.fail()) << line;
    EXPECT_EQ(c1, ',');
    // %.9g: nine significant digits.
    EXPECT_NEAR(distance, b.distance, 1e-8 * std::max(1.0, b.distance));
    EXPECT_NEAR(mean, b.depthMean, 1e-8);
    EXPECT_NEAR(lo, b.depthMin, 1e-8);
    EXPECT_NEAR(hi, b.depthMax, 1e-8);
    ++rows;
  }
  EXPECT_EQ(rows, m.profile.size());
}

}  // namespace
}  // namespace ejecta::fields
