// The 3D oblique Whipple scene (scenes/whipple_sph/oblique_45_3d.toml; label `slow`: minutes):
// the half model on its mirror plane runs through the bumper at 0.8 mm, and the [shield]
// analysis reports the whole shield's debris cloud: it carries the projectile's sideways
// momentum downrange (+x), less than the projectile brought (the bumper takes some), and none
// across the mirror plane; energy is kept.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <unistd.h>

#include "fields/shield_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {
namespace {

TEST(SlowWhippleOblique, TheHalfModelsCloudCarriesTheShotDownrange) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_whipple_oblique_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  std::vector<std::string> coarse = {"time.t_end=10 us"};
  for (int b = 0; b < 3; ++b) coarse.push_back("bodies[" + std::to_string(b) + "].spacing=0.8 mm");
  const Scene scene = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/whipple_sph/oblique_45_3d.toml", coarse);
  const auto frame = shieldFrameFromScene(scene);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->mirrorCopies(), 2);
  EXPECT_NEAR(frame->shotPoint[0], 0.0, 0.01e-3);  // the path crosses the bumper at the origin
  RunOptions options;
  options.outDir = dir.string();
  options.configure = [](const Scene& s, RunOptions& o) { addShieldOutputs(o, s); };
  const RunOutcome r = runScene(scene, options);
  ASSERT_TRUE(r.ok) << r.error;
  const RunSummary& s = r.summary;
  // The projectile (both halves): 2785 kg/m^3, 5 mm, 6.5 km/s at 45 degrees.
  const double mass = 2785.0 * std::numbers::pi / 6.0 * 125e-9;
  const double sideways = mass * 4596.0;
  std::printf("cloud %.4g g (projectile %.4g g), normal momentum %.4g, sideways %.4g kg m/s (projectile %.4g), "
              "leading edge %.3g mm, half-angle %.3g deg; energy error %.2e; %ld steps, %.1f s\n",
              s.number("shield_cloud_mass_kg") * 1e3, mass * 1e3, s.number("shield_cloud_momentum_kg_m_s"),
              s.number("shield_cloud_lateral_momentum_kg_m_s"), sideways, s.number("shield_cloud_leading_edge_m") * 1e3,
              s.number("shield_cloud_half_angle_deg"), s.energy.relativeError, s.steps, s.wallSeconds);
  // Through the bumper: more mass than the projectile's (bumper debris joins it), moving on.
  EXPECT_GT(s.number("shield_cloud_mass_kg"), mass);
  EXPECT_GT(s.number("shield_cloud_leading_edge_m"), 10e-3);
  // Downrange, not across the mirror: the sideways momentum is along +x, a good part of the
  // projectile's and no more than it (the bumper, at rest, takes some).
  EXPECT_GT(s.number("shield_cloud_lateral_momentum_kg_m_s"), 0.3 * sideways);
  EXPECT_LT(s.number("shield_cloud_lateral_momentum_kg_m_s"), 1.05 * sideways);
  EXPECT_LT(std::abs(s.energy.relativeError), 1e-3);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ejecta::fields
