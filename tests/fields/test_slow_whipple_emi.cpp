// The four gas-gun shots of the seed's Table 5.3 as shipped: 0.2 mm (8 particles through the
// bumper, 16 through the wall) and Courant factor 0.15 (label `slow`: about an hour on 2 cores).
// The verification test runs them at 0.4 mm (test_verify_whipple_emi.cpp); both must give
// the experiment's verdicts for EMI 20.1, 21.0 and 71.0 (NP, NP, P) and the ballistic-limit
// equations' for EMI 19.0 (P, where the seed's table's NP is in doubt; there, and docs/whipple.md).
// At 0.2 mm EMI 19.0 perforates at Courant 0.15 (a 2.1 mm hole) and 0.3 (1.3 mm).
#include <gtest/gtest.h>

#include "support/whipple_shots.hpp"

namespace ejecta::fields {
namespace {

RunSummary shoot(const std::string& name) { return test::runWhippleShot(name, "0.2 mm"); }

TEST(SlowWhippleEmi, Emi19PerforatedAsTheEquationsSay) { EXPECT_TRUE(shoot("emi_19").flag("shield_perforated")); }
TEST(SlowWhippleEmi, Emi20_1Held) { EXPECT_FALSE(shoot("emi_20_1").flag("shield_perforated")); }
TEST(SlowWhippleEmi, Emi21Held) { EXPECT_FALSE(shoot("emi_21").flag("shield_perforated")); }
TEST(SlowWhippleEmi, Emi71Perforated) { EXPECT_TRUE(shoot("emi_71").flag("shield_perforated")); }

}  // namespace
}  // namespace ejecta::fields
