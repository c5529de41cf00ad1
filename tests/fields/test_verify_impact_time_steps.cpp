// Verification (label `verification`): the RZ kinetic impact of scenes/impact_rz.toml (granite
// core, rubble crust, aluminium impactor at 10 km/s; strength, fracture, three materials) with
// individual time steps against the same run with global ones: the crater at 3 ms
// (docs/time_steps.md, docs/impact.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include "fields/run_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {
namespace {

RunSummary runImpact(const std::string& stepping) {
  const fs::path dir = fs::temp_directory_path() /
                       ("ejecta_impact_steps_" + stepping + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const Scene scene = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/impact_rz.toml",
                                {"time.stepping=" + stepping});
  RunOptions options;
  options.outDir = dir.string();
  options.configure = [](const Scene& s, RunOptions& o) { addFieldOutputs(o, s); };
  const RunOutcome r = runScene(scene, options);
  EXPECT_TRUE(r.ok) << r.error;
  fs::remove_all(dir);
  return r.summary;
}

TEST(VerifyImpactTimeSteps, TheRzCraterAt3msIsTheGlobalStepsCrater) {
  const RunSummary global = runImpact("global");
  const RunSummary individual = runImpact("individual");
  const double spacing = 0.25;  // [m], the scene's particle spacing
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
  // spacing is halved, docs/impact.md): the time stepping must change it by much less, within
  // one particle spacing in depth and diameter and 5% in volume. Measured: depth +0.04 m,
  // apparent diameter -0.18 m, volume -2.6%.
  EXPECT_NEAR(individual.number("crater_depth_m"), global.number("crater_depth_m"), spacing);
  EXPECT_NEAR(individual.number("crater_apparent_diameter_m"),
              global.number("crater_apparent_diameter_m"), spacing);
  EXPECT_NEAR(individual.number("crater_volume_m3") / global.number("crater_volume_m3"), 1.0, 0.05);
  // The contact at 10 km/s is where the steps differ most: measured energy error 5.4e-3 (global
  // 4.0e-4); 1.5e-2 bounds it. Particle-steps measured 0.38 of the global run's; 0.5 bounds it.
  EXPECT_LT(std::abs(individual.energy.relativeError), 1.5e-2);
  EXPECT_LT(static_cast<double>(individual.integer("particle_updates")),
            0.5 * static_cast<double>(global.particles) * static_cast<double>(global.steps));
}

}  // namespace
}  // namespace ejecta::fields
