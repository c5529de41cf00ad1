// Verification (label `verification`): the four gas-gun shots of the seed's Table 5.3 (EMI 19.0,
// 20.1, 21.0 and 71.0; scenes/whipple_sph/) give the experiment's verdict: a 1.6 mm Al-2024
// bumper and a 3.2 mm Al-2024 wall stop 5 mm spheres at 3.31, 5.5 and 7.2 km/s, and an 8 mm
// sphere at 5.1 km/s perforates the wall. The verdict is the run's own (fields/shield_analysis:
// a through-thickness column of failed wall, or material behind the wall), not read off a
// picture. Run at 0.4 mm, half the shipped scenes' resolution (4 particles through the
// bumper, 8 through the wall), so that the four fit in CI's minutes. Near the ballistic limit the
// verdict moves with the resolution: at the shipped 0.2 mm EMI 19.0 is holed by a hair, and at
// 0.533 mm EMI 71.0 holds; EMI 19.0's also moves with the time step (holed at 0.4 mm with the
// Courant factor halved, as the ballistic-limit equations say). docs/whipple.md gives each
// shot's verdict at four spacings and three Courant factors, and how it moves with the standoff
// the seed does not give.
#include <gtest/gtest.h>

#include "support/whipple_shots.hpp"

namespace ejecta::fields {
namespace {

// 4 particles through the bumper, 8 through the wall.
RunSummary shoot(const std::string& name) { return test::runWhippleShot(name, "0.4 mm"); }

TEST(VerifyWhippleEmi, Emi19FiveMillimetresAt3_31KmsHeld) {
  const RunSummary s = shoot("emi_19");
  EXPECT_FALSE(s.flag("shield_perforated"));
  // The wall is struck and dents (the debris reaches it): a verdict on a wall nothing reached
  // would be empty.
  EXPECT_GT(s.number("shield_peak_deflection_m"), 0.0);
}

TEST(VerifyWhippleEmi, Emi20_1FiveMillimetresAt5_5KmsHeld) {
  const RunSummary s = shoot("emi_20_1");
  EXPECT_FALSE(s.flag("shield_perforated"));
  EXPECT_GT(s.number("shield_peak_deflection_m"), 0.0);
}

TEST(VerifyWhippleEmi, Emi21FiveMillimetresAt7_2KmsHeld) {
  const RunSummary s = shoot("emi_21");
  EXPECT_FALSE(s.flag("shield_perforated"));
  EXPECT_GT(s.number("shield_peak_deflection_m"), 0.0);
}

TEST(VerifyWhippleEmi, Emi71EightMillimetresAt5_1KmsPerforated) {
  const RunSummary s = shoot("emi_71");
  EXPECT_TRUE(s.flag("shield_perforated"));
}

}  // namespace
}  // namespace ejecta::fields
