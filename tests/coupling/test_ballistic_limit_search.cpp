// The ballistic-limit search's machinery (coupling/ballistic_limit_search, issue 21) on a tiny RZ
// shield whose verdicts are known without physics: a wall nothing reaches in the run's time
// holds against every diameter (the limit lies above the bracket), a wall that starts failed
// is perforated by every one (below it); the shield the equations see is the scene's; shots
// already run are read back, not run again. The search against real shots is
// test_slow_whipple_limit.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "coupling/ballistic_limit_search.hpp"
#include "radiation/whipple.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {
namespace {

// A 0.5 mm bumper and a 1 mm wall 5 mm behind it, 0.25 mm particles; 1 us is too short for
// anything to cross the gap. `wallDamage` 1: the wall starts failed through its thickness.
std::string shieldScene(double wallDamage) {
  return R"(
[scene]
name = "tiny_shield"
dimension = "rz"
[sph]
density = "continuity"
form = "interface"
[time]
t_end = "1 us"
[output]
snapshot_interval = "1 us"
[crater]
enabled = false
[shield]
wall = "wall"
bumper = "bumper"
[[materials]]
name = "al"
eos = "mie_gruneisen"
library = "Al-2024"
[materials.strength]
model = "johnson_cook"
library = "Al-2024-T351"
[materials.fracture]
model = "principal_stress"
tensile_strength = "2.5 GPa"
[[materials]]
name = "wall_al"
eos = "mie_gruneisen"
library = "Al-2024"
[materials.strength]
model = "johnson_cook"
library = "Al-2024-T351"
[materials.fracture]
model = "principal_stress"
tensile_strength = "2.5 GPa"
[[bodies]]
name = "projectile"
material = "al"
shape = "sphere"
center = [0.0, "1.2 mm"]
radius = "1 mm"
spacing = "0.25 mm"
density = "2785 kg/m^3"
pressure = 0.0
velocity = [0.0, "-3 km/s"]
[[bodies]]
name = "bumper"
material = "al"
shape = "box"
min = [0.0, "-0.5 mm"]
max = ["4 mm", 0.0]
spacing = "0.25 mm"
density = "2785 kg/m^3"
pressure = 0.0
[[bodies]]
name = "wall"
material = "wall_al"
shape = "box"
min = [0.0, "-6.5 mm"]
max = ["4 mm", "-5.5 mm"]
spacing = "0.25 mm"
density = "2785 kg/m^3"
pressure = 0.0
damage = )" + std::to_string(wallDamage) + "\n";
}

LimitSearchOptions options(const fs::path& dir, int* ran) {
  LimitSearchOptions o;
  o.speeds = {3e3};
  o.smallest = 0.5e-3;
  o.largest = 2e-3;
  o.iterations = 3;
  o.outDir = dir;
  o.onShot = [ran](double, double, bool, double seconds) { *ran += seconds >= 0.0; };
  return o;
}

TEST(BallisticLimitSearch, TheEquationsSeeTheScenesShield) {
  const Scene scene = parseScene(shieldScene(0.0), "tiny.toml");
  const radiation::WhippleShield s = shieldOfScene(scene, std::nullopt);
  EXPECT_NEAR(s.bumperThickness, 0.5e-3, 1e-15);
  EXPECT_NEAR(s.wallThickness, 1e-3, 1e-15);
  EXPECT_NEAR(s.standoff, 5e-3, 1e-15);
  EXPECT_EQ(s.bumperDensity, 2785.0);
  EXPECT_EQ(s.wallYieldStress, 265e6);  // Johnson & Cook (1983), 2024-T351: A
  EXPECT_EQ(shieldOfScene(scene, 400e6).wallYieldStress, 400e6);
}

TEST(BallisticLimitSearch, AWallNothingReachesHoldsAndShotsAreNotRunTwice) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_limit_held_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  int ran = 0;
  const LimitSearchResult r = searchBallisticLimits(shieldScene(0.0), "tiny.toml", options(dir, &ran));
  ASSERT_EQ(r.limits.size(), 1u);
  // Both ends held: no bisection, the limit lies above the bracket.
  EXPECT_EQ(ran, 2);
  EXPECT_EQ(r.shots.size(), 2u);
  EXPECT_FALSE(r.shots[0].perforated);
  EXPECT_FALSE(r.shots[1].perforated);
  ASSERT_TRUE(r.limits[0].largestHeld);
  EXPECT_EQ(*r.limits[0].largestHeld, 2e-3);
  EXPECT_FALSE(r.limits[0].critical);
  EXPECT_FALSE(r.limits[0].smallestPerforating);
  // The equations' limit for the same shield and projectile, head on.
  EXPECT_NEAR(r.impactAngle, 0.0, 1e-15);
  EXPECT_EQ(r.limits[0].equations.diameter,
            radiation::criticalDiameter(r.shield, 2785.0, 3e3, 0.0).diameter);
  // Again: both shots are read back from their run directories.
  int again = 0;
  const LimitSearchResult second = searchBallisticLimits(shieldScene(0.0), "tiny.toml", options(dir, &again));
  EXPECT_EQ(again, 0);
  EXPECT_EQ(*second.limits[0].largestHeld, 2e-3);
  EXPECT_NE(limitsCsv(second).find("speed_m_s,largest_held_m"), std::string::npos);
  EXPECT_NE(shotsCsv(second).find("3000,0.002,0,intact"), std::string::npos) << shotsCsv(second);
  fs::remove_all(dir);
}

TEST(BallisticLimitSearch, AFailedWallIsPerforatedByTheSmallestShot) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_limit_failed_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  int ran = 0;
  const LimitSearchResult r = searchBallisticLimits(shieldScene(1.0), "tiny.toml", options(dir, &ran));
  EXPECT_EQ(ran, 1);  // the smallest perforates: the limit lies below the bracket
  ASSERT_TRUE(r.limits[0].smallestPerforating);
  EXPECT_EQ(*r.limits[0].smallestPerforating, 0.5e-3);
  EXPECT_EQ(r.shots[0].reason, "hole");
  fs::remove_all(dir);
}

TEST(BallisticLimitSearch, RefusesABadBracket) {
  LimitSearchOptions o;
  o.speeds = {3e3};
  o.smallest = 2e-3;
  o.largest = 1e-3;
  EXPECT_THROW(searchBallisticLimits(shieldScene(0.0), "tiny.toml", o), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::coupling
