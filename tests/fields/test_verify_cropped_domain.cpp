// Verification (label `verification`): the cropped 3D domain of
// scenes/impact_3d_oblique_cropped.toml (the asteroid cut to a box 15 m about the impact point,
// open faces) against the whole asteroid of scenes/impact_3d_oblique.toml, the same impact at
// the same coarse spacing, to 3 ms: the crater and the coupled energy must be the whole body's
// (issue 23, "model no more than a scene needs"; docs/impact.md, "A cropped 3D domain").
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "support/shipped_impact_run.hpp"

namespace ejecta::fields {
namespace {

// The scene at a coarse spacing (impactor 1 m, asteroid 2 m: the full body is 22,000 particles),
// with its crater measured.
RunSummary runCoarse(const std::string& file) {
  return test::runShippedScene(file,
                               {"bodies[0].spacing=1 m", "bodies[1].spacing=2 m",
                                "bodies[2].spacing=2 m", "fields.every=1000"},
                               "crop_" + file);
}

// A scene file's lines that make the scene: comments and blank lines dropped, and those the
// cropped scene may differ in (its name, description, [domain] and spacing) set aside.
std::vector<std::string> sceneLines(const std::string& file) {
  std::ifstream in(std::string(EJECTA_SOURCE_DIR) + "/scenes/" + file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const bool differs = line.starts_with("name = \"impact_3d") || line.starts_with("description =") ||
                         line == "[domain]" || line.starts_with("x = {") || line.starts_with("y = {") ||
                         line.starts_with("z = {") || line.starts_with("spacing =");
    if (!differs) lines.push_back(line);
  }
  return lines;
}

TEST(VerifyCroppedDomain, TheCroppedSceneIsTheWholeSceneButForItsDomainAndSpacing) {
  // Two files, one impact: a material or body edited in one and not the other would make the
  // comparison below, and the docs' numbers, about two different impacts.
  const std::vector<std::string> whole = sceneLines("impact_3d_oblique.toml");
  const std::vector<std::string> cropped = sceneLines("impact_3d_oblique_cropped.toml");
  ASSERT_GT(whole.size(), 50u);
  EXPECT_EQ(cropped, whole);
  const Scene c = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/impact_3d_oblique_cropped.toml");
  for (const BodySpec& b : c.bodies) EXPECT_EQ(b.spacing, 0.5) << b.name;
  for (const AxisBounds& axis : c.domain) EXPECT_TRUE(axis.bounded);
}

TEST(VerifyCroppedDomain, TheCroppedAsteroidGivesTheWholeAsteroidsCraterAt3ms) {
  const RunSummary whole = runCoarse("impact_3d_oblique.toml");
  const RunSummary cropped = runCoarse("impact_3d_oblique_cropped.toml");
  std::printf("oblique impact at 3 ms, whole / cropped asteroid: %zu / %zu particles, depth %.3f / "
              "%.3f m, apparent diameter %.3f / %.3f m, volume %.1f / %.1f m^3, target share %.5f / "
              "%.5f, wall %.2f / %.2f s\n",
              whole.particles, cropped.particles, whole.number("crater_depth_m"),
              cropped.number("crater_depth_m"), whole.number("crater_apparent_diameter_m"),
              cropped.number("crater_apparent_diameter_m"), whole.number("crater_volume_m3"),
              cropped.number("crater_volume_m3"), whole.number("target_share_of_impactor_energy"),
              cropped.number("target_share_of_impactor_energy"), whole.wallSeconds, cropped.wallSeconds);
  ASSERT_TRUE(whole.flag("crater_found") && cropped.flag("crater_found"));
  // The box keeps a fifteenth of the particles (measured 1,482 of 22,408).
  EXPECT_LT(cropped.particles * 10, whole.particles);
  // The disturbance reaches the box's faces at about 2 ms, and what they reflect has not come
  // back to change the crater by 3 ms. Measured at this spacing: depth -0.6%, apparent diameter
  // +0.13%, volume -0.35%, target share -0.001% (at the shipped 1 m spacing of the full body:
  // 0.005%, 0.02%, 0.04%). Bounds: 2% on the crater (as issue 18 asks of another change of
  // method on the same crater), 0.1% on the share.
  EXPECT_NEAR(cropped.number("crater_depth_m") / whole.number("crater_depth_m"), 1.0, 0.02);
  EXPECT_NEAR(cropped.number("crater_apparent_diameter_m") /
                  whole.number("crater_apparent_diameter_m"),
              1.0, 0.02);
  EXPECT_NEAR(cropped.number("crater_volume_m3") / whole.number("crater_volume_m3"), 1.0, 0.02);
  EXPECT_NEAR(cropped.number("target_share_of_impactor_energy") /
                  whole.number("target_share_of_impactor_energy"),
              1.0, 1e-3);
}

}  // namespace
}  // namespace ejecta::fields
