// Ballistic limits from simulation against Christiansen's equations (issue 21; label `slow`,
// about half an hour on 2 cores): the EMI shield of the seed's Table 5.3 (1.6 mm Al-2024 bumper,
// 3.2 mm wall, 100 mm standoff; scenes/whipple_sph/emi_21.toml with its projectile resized and
// re-aimed by `ejecta whipple-limit`'s search) at 0.4 mm, 80 us and the scene's Courant factor
// 0.15, at 3, 5 and 7 km/s: the bracket of diameters is 2-16 mm and three bisections narrow it to
// a factor 1.3.
// The criterion is the equations' own scatter against experiments (docs/whipple.md, "How far the
// equations scatter"): in each speed band of pyBLOSSUM's 1,135-shot database, shots held up to
// r = d / d_c of 1.72, 1.51 and 1.43 and perforated down to 0.74, 0.51 and 0.44 (3, 5, 7 km/s).
// The simulated limit's ratio to the equations' must lie in that band, where experiments give
// both outcomes.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "coupling/ballistic_limit_search.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {
namespace {

struct Band {
  double speed, smallestPerforated, largestHeld;
};

TEST(SlowWhippleLimit, TheSimulatedLimitLiesInTheEquationsScatter) {
  std::ifstream in(std::string(EJECTA_SOURCE_DIR) + "/scenes/whipple_sph/emi_21.toml");
  std::stringstream text;
  text << in.rdbuf();
  LimitSearchOptions o;
  o.speeds = {3e3, 5e3, 7e3};
  o.smallest = 2e-3;
  o.largest = 16e-3;
  o.iterations = 3;
  o.overrides = {"time.t_end=80 us"};
  for (int b = 0; b < 3; ++b) o.overrides.push_back("bodies[" + std::to_string(b) + "].spacing=0.4 mm");
  o.outDir = fs::temp_directory_path() / ("ejecta_slow_limit_" + std::to_string(::getpid()));
  fs::remove_all(o.outDir);
  const LimitSearchResult r = searchBallisticLimits(text.str(), "emi_21.toml", o);
  std::printf("%s", limitsCsv(r).c_str());
  const Band bands[] = {{3e3, 0.74, 1.72}, {5e3, 0.51, 1.51}, {7e3, 0.44, 1.43}};
  ASSERT_EQ(r.limits.size(), 3u);
  for (const Band& band : bands) {
    const SpeedLimit* limit = nullptr;
    for (const SpeedLimit& l : r.limits)
      if (l.speed == band.speed) limit = &l;
    ASSERT_TRUE(limit);
    ASSERT_TRUE(limit->critical) << "no bracket at " << band.speed << " m/s: the limit lies outside 2-16 mm";
    const double ratio = *limit->critical / limit->equations.diameter;
    std::printf("%.0f km/s: simulated d_c %.3g mm (%.3g-%.3g), equations %.3g mm, ratio %.2f; experiments "
                "gave both outcomes for ratios %.2f-%.2f\n",
                band.speed * 1e-3, *limit->critical * 1e3, *limit->largestHeld * 1e3,
                *limit->smallestPerforating * 1e3, limit->equations.diameter * 1e3, ratio,
                band.smallestPerforated, band.largestHeld);
    EXPECT_GE(ratio, band.smallestPerforated) << band.speed << " m/s";
    // Known today at 3 and 5 km/s (ratios 1.89 and 1.70; 2.0 and 1.6 at Courant 0.3): the
    // simulated shield holds more than any shot of the database did at those speeds
    // (docs/whipple.md, "Ballistic limits from simulation" and "The time step, measured").
    EXPECT_LE(ratio, band.largestHeld) << band.speed << " m/s: the simulation is not conservative here";
  }
  fs::remove_all(o.outDir);
}

}  // namespace
}  // namespace ejecta::coupling
