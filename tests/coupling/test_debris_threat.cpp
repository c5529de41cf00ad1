// The debris the follower meets (coupling/debris_threat, issue 21): constructed fragments on
// and off a 1 m box's path at 10 km/s, with the closest approach, relative speed and angle
// worked out by hand, and the ballistic-limit verdict of the seed's HAIV shield on a 5 mm
// granite fragment met head on (d_c = 4.43 mm: it perforates; docs/whipple.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coupling/debris_threat.hpp"

namespace ejecta::coupling {
namespace {

constexpr double kPi = std::numbers::pi;

// A 1 m box starting 10 m up the y axis, flying down it at 10 km/s for 1 ms.
radiation::ThermalStudy follower() {
  radiation::ThermalStudy s;
  s.source = "follower.toml";
  s.spacecraft.body.kind = radiation::SurfaceShape::Kind::Box;
  s.spacecraft.body.size = {1.0, 1.0, 1.0};
  s.approach.start = {0.0, 10.0, 0.0};
  s.approach.velocity = {0.0, -1e4, 0.0};
  s.approach.duration = 1e-3;
  return s;
}

fields::Fragment fragment(std::array<double, 3> x, std::array<double, 3> v, double diameter,
                          double density = 2680.0, bool resolved = true) {
  fields::Fragment f;
  f.particles = 100;
  f.center = x;
  f.velocity = v;
  f.diameter = diameter;
  f.volume = kPi / 6.0 * diameter * diameter * diameter;
  f.mass = density * f.volume;
  f.resolved = resolved;
  return f;
}

fields::FragmentCensus census(Geometry g, std::vector<fields::Fragment> fragments) {
  fields::FragmentCensus c;
  c.geometry = g;
  c.fragments = std::move(fragments);
  return c;
}

// The seed's HAIV shield (scenes/whipple/haiv.toml).
radiation::WhippleShield haiv() {
  return {.bumperThickness = 1.6e-3, .bumperDensity = 2713, .wallThickness = 3.2e-3, .wallDensity = 2713,
          .wallYieldStress = 37 * radiation::kPascalPerKsi, .standoff = 0.10};
}

TEST(DebrisThreat, FragmentsOnThePathAreMetAndThoseOffItAreNot) {
  const fields::FragmentCensus c = census(
      Geometry::Spatial,
      {fragment({0, 5, 0}, {0, 0, 0}, 5e-3),            // on the path, at rest: met at 0.5 ms
       fragment({3, 5, 0}, {0, 0, 0}, 5e-3),            // 3 m to the side: missed
       fragment({0, 20, 0}, {0, 0, 0}, 5e-3),           // behind the start: nearest at t = 0, 10 m
       fragment({-5, 5, 0}, {1e4, 0, 0}, 5e-3),         // crosses the path as the box passes
       fragment({0, 12, 0}, {0, 2e4, 0}, 5e-3)});       // ahead... above it, flying away
  const DebrisThreat t = assessDebrisThreat(c, follower(), std::nullopt);
  // The box's bounding radius: half its diagonal, sqrt(3)/2 m.
  EXPECT_NEAR(t.spacecraftRadius, std::sqrt(3.0) / 2.0, 1e-12);
  ASSERT_EQ(t.encounters.size(), 2u);
  for (const Encounter& e : t.encounters) {
    EXPECT_NEAR(e.time, 0.5e-3, 1e-12);
    EXPECT_NEAR(e.missDistance, 0.0, 1e-9);
    EXPECT_FALSE(e.limit);
  }
  const Encounter& still = t.encounters[0].fragment == 0 ? t.encounters[0] : t.encounters[1];
  const Encounter& crossing = t.encounters[0].fragment == 3 ? t.encounters[0] : t.encounters[1];
  EXPECT_EQ(still.fragment, 0u);
  EXPECT_NEAR(still.speed, 1e4, 1e-6);
  EXPECT_NEAR(still.angle, 0.0, 1e-9);  // head on
  EXPECT_EQ(crossing.fragment, 3u);
  // Relative velocity (10, 10, 0) km/s: 14.1 km/s, 45 degrees off the flight direction.
  EXPECT_NEAR(crossing.speed, std::sqrt(2.0) * 1e4, 1e-6);
  EXPECT_NEAR(crossing.angle, kPi / 4.0, 1e-12);
  EXPECT_NEAR(still.density, 2680.0, 1e-9);
}

TEST(DebrisThreat, TheShieldStopsWhatTheEquationsSayItStops) {
  // 5 mm of granite head on at 10 km/s against the HAIV shield: d_c = 4.43 mm, perforated; a
  // 3.83 mm wall would stop it (radiation/whipple.hpp; the numbers of docs/whipple.md). A 3 mm
  // fragment is stopped.
  const fields::FragmentCensus c = census(
      Geometry::Spatial, {fragment({0, 5, 0}, {0, 0, 0}, 5e-3), fragment({0.2, 4, 0}, {0, 0, 0}, 3e-3, 2680.0, false)});
  const DebrisThreat t = assessDebrisThreat(c, follower(), haiv());
  ASSERT_EQ(t.encounters.size(), 2u);
  const Encounter& big = t.encounters[0];
  ASSERT_TRUE(big.limit);
  EXPECT_NEAR(big.limit->diameter, 4.43e-3, 0.01e-3);
  EXPECT_TRUE(big.perforates);
  EXPECT_NEAR(big.requiredWall, 3.83e-3, 0.01e-3);
  const Encounter& small = t.encounters[1];
  EXPECT_FALSE(small.perforates);
  EXPECT_LT(small.requiredWall, haiv().wallThickness);  // a thinner wall would do
  EXPECT_EQ(t.perforating, 1u);
  EXPECT_EQ(t.perforatingResolved, 1u);
  EXPECT_NEAR(t.requiredWall, big.requiredWall, 1e-15);
  EXPECT_NEAR(t.requiredWallResolved, big.requiredWall, 1e-15);
  const std::string csv = encountersCsv(t);
  EXPECT_NE(csv.find("fragment,time_s,miss_distance_m,speed_m_s,angle_deg"), std::string::npos);
}

TEST(DebrisThreat, RzRingsAreMetByTheirNearestPieceOnAnAxialPass) {
  // A ring of radius 0.5 m at height 5 m: its nearest piece passes 0.5 m from the box's centre.
  const fields::FragmentCensus c =
      census(Geometry::Axisymmetric, {fragment({0.5, 5, 0}, {100, 0, 0}, 0.1), fragment({2.0, 5, 0}, {0, 0, 0}, 0.1)});
  const DebrisThreat t = assessDebrisThreat(c, follower(), std::nullopt);
  ASSERT_EQ(t.encounters.size(), 1u);
  EXPECT_EQ(t.encounters[0].fragment, 0u);
  EXPECT_LT(t.encounters[0].missDistance, 0.6);
  // Off the axis an RZ run's debris cannot be placed around the spacecraft: refused.
  radiation::ThermalStudy off = follower();
  off.approach.start[0] = 1.0;
  EXPECT_THROW(assessDebrisThreat(c, off, std::nullopt), std::invalid_argument);
  EXPECT_THROW(assessDebrisThreat(census(Geometry::Planar, {}), follower(), std::nullopt), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::coupling
