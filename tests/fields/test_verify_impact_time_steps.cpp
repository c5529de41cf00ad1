// Verification (label `verification`): individual time steps against the same run with global
// ones on the RZ kinetic impact of scenes/impact_rz.toml (granite core, rubble crust, aluminium
// impactor at 10 km/s; strength, fracture, three materials: the crater at 3 ms) and on the
// follower's 100 kt burst in that crater, scenes/case2_rz_follower.toml (the coupled share and
// the crater at 8 ms); docs/time_steps.md, docs/impact.md, docs/asteroid_studies.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/shipped_impact_run.hpp"

namespace ejecta::fields {
namespace {

RunSummary runImpact(const std::string& stepping, const std::string& file = "impact_rz.toml",
                     const std::vector<std::string>& extra = {}) {
  std::vector<std::string> overrides = extra;
  overrides.push_back("time.stepping=" + stepping);
  return test::runShippedScene(file, overrides, "impact_steps_" + stepping);
}

// Both runs with [time] closing_speed (docs/time_steps.md, "Bodies that meet"): the impactor's
// first contact is a one-sided kernel closing at 10 km/s. Without it, measured: depth +0.55%,
// apparent diameter -2.3%, volume -2.6%, rim height +13%, energy error 5.4e-3 (global 4.0e-4),
// particle-steps 0.38 of global; outside issue 18's 2% for the crater.
TEST(VerifyImpactTimeSteps, TheRzCraterAt3msIsTheGlobalStepsCrater) {
  const std::vector<std::string> closing{"time.closing_speed=true"};
  const RunSummary global = runImpact("global", "impact_rz.toml", closing);
  const RunSummary individual = runImpact("individual", "impact_rz.toml", closing);
  std::printf("crater at 3 ms, global / individual: depth %.3f / %.3f m, apparent diameter "
              "%.3f / %.3f m, volume %.1f / %.1f m^3; particle-steps %.3g / %lld; wall %.1f / "
              "%.1f s; energy error %.2e / %.2e\n",
              global.number("crater_depth_m"), individual.number("crater_depth_m"),
              global.number("crater_apparent_diameter_m"),
              individual.number("crater_apparent_diameter_m"), global.number("crater_volume_m3"),
              individual.number("crater_volume_m3"),
              static_cast<double>(global.particles) * static_cast<double>(global.steps),
              static_cast<long long>(individual.integer("particle_updates")), global.wallSeconds,
              individual.wallSeconds, global.energy.relativeError,
              individual.energy.relativeError);
  ASSERT_TRUE(individual.flag("crater_found"));
  // At this spacing the crater is far from converged (it moves by tens of percent when the
  // spacing is halved, docs/impact.md): the time stepping must change it by much less, issue
  // 18's 2% in depth, diameter and volume. Measured: +0.03%, +0.08%, +0.06%.
  EXPECT_NEAR(individual.number("crater_depth_m") / global.number("crater_depth_m"), 1.0, 0.02);
  EXPECT_NEAR(individual.number("crater_apparent_diameter_m") /
                  global.number("crater_apparent_diameter_m"), 1.0, 0.02);
  EXPECT_NEAR(individual.number("crater_volume_m3") / global.number("crater_volume_m3"), 1.0, 0.02);
  // Energy error measured 1.7e-4 (global 7.7e-6); 1e-3 bounds it. Particle-steps measured 0.34
  // of the global run's (the global run takes 13% more steps with the criterion, the individual
  // one as many particle-steps as without it); 0.5 bounds it.
  EXPECT_LT(std::abs(individual.energy.relativeError), 1e-3);
  EXPECT_LT(static_cast<double>(individual.integer("particle_updates")),
            0.5 * static_cast<double>(global.particles) * static_cast<double>(global.steps));
}

TEST(VerifyImpactTimeSteps, TheFollowersBurstInTheRealCraterCouplesAsWithGlobalSteps) {
  // The case individual steps are for (scenes/case2_rz_follower.toml): the impactor's crater,
  // then the follower's 100 kt DED at 3 ms into 6 particles (3.7e10 J/kg), run to 8 ms. With
  // global steps every particle then steps at the device's ~1e-6 s.
  const RunSummary global = runImpact("global", "case2_rz_follower.toml");
  const RunSummary individual = runImpact("individual", "case2_rz_follower.toml");
  const double spacing = 0.5;  // [m]
  std::printf("case 2 follower, global / individual: target share %.4f / %.4f, crater depth "
              "%.2f / %.2f m; particle-steps %.3g / %lld; wall %.1f / %.1f s; energy error "
              "%.2e / %.2e\n",
              global.number("target_share_of_yield"), individual.number("target_share_of_yield"),
              global.number("crater_depth_m"), individual.number("crater_depth_m"),
              static_cast<double>(global.particles) * static_cast<double>(global.steps),
              static_cast<long long>(individual.integer("particle_updates")), global.wallSeconds,
              individual.wallSeconds, global.energy.relativeError,
              individual.energy.relativeError);
  // The coupled share of the yield, the study's answer: measured 0.694 against 0.679 (+2.3%);
  // it moves by tens of percent with the spacing (docs/asteroid_studies.md), so 3% bounds the
  // time stepping's part. At the scene's settings only: with the Courant number or the closing
  // speed changed, the two differ by -3.5% to +4.4% with no trend as the step falls, and the
  // global runs alone span 9% (docs/time_steps.md, "Not yet": a few of the six-particle device's
  // and impactor's particles carry percents of the yield), so a change that moves this run's
  // bits can move the ratio by that much without being wrong.
  EXPECT_NEAR(individual.number("target_share_of_yield") / global.number("target_share_of_yield"),
              1.0, 0.03);
  // The crater after the burst: measured 16.7 m against 17.5 m, two spacings (the device is six
  // particles); three bound it.
  EXPECT_NEAR(individual.number("crater_depth_m"), global.number("crater_depth_m"), 3 * spacing);
  // Measured energy error 5.9e-3 (global 1.9e-4); 0.015 bounds it. Particle-steps: measured
  // 0.109 of the global run's (0.071 until particles in no pair stopped setting the global
  // step: the global run fell from ~3.2e7 to 2.1e7 particle-steps, the individual one is
  // unchanged); 0.15 bounds it.
  EXPECT_LT(std::abs(individual.energy.relativeError), 1.5e-2);
  EXPECT_LT(static_cast<double>(individual.integer("particle_updates")),
            0.15 * static_cast<double>(global.particles) * static_cast<double>(global.steps));
}

}  // namespace
}  // namespace ejecta::fields
