#pragma once
// A shipped Whipple-shield scene (scenes/whipple_sph/) run at a chosen spacing with the [shield]
// analysis, its verdict and measures printed: shared by the EMI verification (0.4 mm) and the
// full-resolution study (label slow).
#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "fields/shield_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::test {

inline RunSummary runWhippleShot(const std::string& name, const std::string& spacing,
                                 std::vector<std::string> overrides = {}) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ejecta_whipple_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  for (int b = 0; b < 3; ++b) overrides.push_back("bodies[" + std::to_string(b) + "].spacing=" + spacing);
  const Scene scene = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/whipple_sph/" + name + ".toml", overrides);
  RunOptions options;
  options.outDir = dir.string();
  options.configure = [](const Scene& s, RunOptions& o) { fields::addShieldOutputs(o, s); };
  const RunOutcome r = runScene(scene, options);
  EXPECT_TRUE(r.ok) << r.error;
  const RunSummary& s = r.summary;
  std::printf("%s at %s: %s (%s); hole %.3g mm, %.3g g behind the wall, peak deflection %.3g mm; cloud %.3g g, "
              "leading %.3g km/s, half-angle %.3g deg; %ld steps, %.1f s\n",
              name.c_str(), spacing.c_str(), s.flag("shield_perforated") ? "perforated" : "held",
              s.text("shield_reason").c_str(), s.number("shield_hole_diameter_m") * 1e3,
              s.number("shield_mass_behind_wall_kg") * 1e3, s.number("shield_peak_deflection_m") * 1e3,
              s.number("shield_cloud_mass_kg") * 1e3, s.number("shield_cloud_leading_speed_m_s") * 1e-3,
              s.number("shield_cloud_half_angle_deg"), s.steps, s.wallSeconds);
  fs::remove_all(dir);
  return s;
}

}  // namespace ejecta::test
