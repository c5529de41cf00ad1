// Verification (label `verification`): the four gas-gun shots of the seed's Table 5.3 (EMI 19.0,
// 20.1, 21.0 and 71.0; scenes/whipple_sph/): a 1.6 mm Al-2024 bumper and a 3.2 mm Al-2024 wall
// stop 5 mm spheres at 5.5 and 7.2 km/s, and an 8 mm sphere at 5.1 km/s perforates the wall. The
// verdict is the run's own (fields/shield_analysis: a through-thickness column of failed wall, or
// material behind the wall), not read off a picture. Run at 0.4 mm, half the shipped scenes'
// resolution (4 particles through the bumper, 8 through the wall), so that the four fit in CI's
// minutes.
// EMI 19.0 (a 5 mm sphere at 3.31 km/s) is the exception. The seed's table says the wall held; the
// ballistic-limit equations put the shot at r = d/d_c = 2.2 (perforated), and no shot of their
// database between 2.5 and 3.5 km/s held beyond r = 1.72, so the table's entry is in doubt (its
// primary report could not be read). The simulation held at the default Courant factor 0.3 only
// because that step was too long: halved (0.15, the shipped scenes' factor) and quartered it
// perforates, as it does at 0.2 mm. So EMI 19.0 is run converged in time and checked against the
// equations' verdict; the other three keep their verdicts, and their bulges move by 0.1 mm, when
// the step is halved, so they run at the default step to fit CI's minutes. docs/whipple.md gives
// each shot's verdict at four spacings and three Courant factors, and how it moves with the
// standoff the seed does not give.
#include <gtest/gtest.h>

#include "support/whipple_shots.hpp"

namespace ejecta::fields {
namespace {

// 4 particles through the bumper, 8 through the wall, at the default step (above).
RunSummary shoot(const std::string& name) { return test::runWhippleShot(name, "0.4 mm", {"sph.courant=0.3"}); }

TEST(VerifyWhippleEmi, Emi19ConvergedInTimePerforatesAsTheEquationsSay) {
  const RunSummary s = test::runWhippleShot("emi_19", "0.4 mm");  // the scene's Courant factor, 0.15
  EXPECT_TRUE(s.flag("shield_perforated"));
}

TEST(VerifyWhippleEmi, Emi20_1FiveMillimetresAt5_5KmsHeld) {
  const RunSummary s = shoot("emi_20_1");
  EXPECT_FALSE(s.flag("shield_perforated"));
  // The wall is struck and dents (the debris reaches it): a verdict on a wall nothing reached
  // would be empty.
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
