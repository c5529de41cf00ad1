// `ejecta run`'s printed summary against its summary.json (apps/cmd_run.cpp): the printed lines
// come from the typed summaries (sim/run/energy_ledger.hpp, sim/run/gauge_summary.hpp,
// fields/crater_summary.hpp) and summary.json from their one serialisation, so every printed
// number must read, at its printed precision, what summary.json holds under its key. A tiny RZ
// impact with a device going off in the target and a gauge between them prints the energy, the
// crater, the source, the coupling and the gauge lines; the same impact with a spacecraft passing
// over the crater (coupling/run_thermal.hpp, coupling/thermal_summary.hpp) prints the thermal lines.
#include <gtest/gtest.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/command_line.hpp"
#include "support/small_follower_study.hpp"
#include "support/tiny_impact.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::readTextFile;
using ejecta::test::runCommand;
using ejecta::test::writeTextFile;

// A 1 MJ device of granite, 0.3 m down in the target (listed first, so it takes its place in the
// target block), and a gauge 0.1 m above it. The crater is the granite's (the device's sphere
// would otherwise be taken for the target's surface).
const char* kDevice = R"(
[crater]
materials = ["granite"]
[[materials]]
name = "device"
eos = "tillotson"
library = "granite"
[[bodies]]
name = "device"
material = "device"
shape = "sphere"
center = [0.0, "-0.3 m"]
radius = "0.05 m"
spacing = "0.02 m"
density = "2680 kg/m^3"
pressure = 0.0
[[energy_deposits]]
name = "yield"
body = "device"
energy = "1 MJ"
[[gauges]]
name = "g1"
position = [0.0, "-0.2 m"]
)";

// The small follower study (tests/support/small_follower_study.hpp).
const char* const kStudy = ejecta::test::kSmallFollowerStudy;

// A printed value: the summary.json entry it shows, the factor it is printed with and its format.
struct Printed {
  nlohmann::json value;
  double scale;
  const char* format;
};

std::string formatted(const Printed& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, p.format, p.scale * p.value.get<double>());
  return buf;
}

// The one line of `output` that matches `pattern` (each number a group), its numbers against the
// expected ones.
void expectLine(const std::string& output, const std::string& pattern,
                const std::vector<Printed>& expected) {
  const std::regex re(pattern);
  std::istringstream lines(output);
  int matches = 0;
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, re)) continue;
    ++matches;
    ASSERT_EQ(m.size(), expected.size() + 1) << line;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      ASSERT_TRUE(expected[k].value.is_number()) << pattern << " value " << k << " in\n" << output;
      EXPECT_EQ(m[k + 1].str(), formatted(expected[k])) << "number " << k << " of: " << line;
    }
  }
  EXPECT_EQ(matches, 1) << pattern << " in\n" << output;
}

TEST(RunSummaryPrinted, EveryPrintedNumberIsTheOneInSummaryJson) {
  const fs::path dir =
      fs::temp_directory_path() / ("ejecta_chain_run_summary_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  ejecta::test::TinyImpact impact;
  impact.extra = kDevice;
  writeTextFile(dir / "tiny.toml", ejecta::test::tinyImpactScene(impact));
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " run " + (dir / "tiny.toml").string() +
                           " --no-charts --threads 2 --out " + (dir / "out").string(),
                       out),
            0)
      << out;
  const nlohmann::json j = nlohmann::json::parse(readTextFile(dir / "out" / "summary.json"));
  const nlohmann::json& x = j.at("extras");
  const std::string number = "([-+0-9.e]+|nan|inf)";

  expectLine(out, "completed: " + number + " particles, " + number + " steps to t = " + number,
             {{j.at("particles"), 1.0, "%.0f"}, {j.at("steps"), 1.0, "%.0f"},
              {j.at("t_end"), 1.0, "%.6g"}});
  expectLine(out,
             "energy: initial " + number + " J, final " + number + " J, relative error " + number,
             {{j.at("energy").at("initial"), 1.0, "%.8g"},
              {j.at("energy").at("final"), 1.0, "%.8g"},
              {j.at("energy").at("relative_error"), 1.0, "%.3g"}});
  ASSERT_TRUE(x.at("crater_found").get<bool>()) << x.dump(2);
  expectLine(out,
             "crater: depth " + number + " m, apparent diameter " + number + " m, rim-to-rim " +
                 number + " m",
             {{x.at("crater_depth_m"), 1.0, "%.3g"},
              {x.at("crater_apparent_diameter_m"), 1.0, "%.3g"},
              {x.at("crater_rim_diameter_m"), 1.0, "%.3g"}});
  expectLine(out,
             "source: yield " + number + " kt \\(" + number + " J\\), depth of burst " + number +
                 " m \\(scaled " + number + " m/kt",
             {{x.at("yield_kt"), 1.0, "%.4g"},
              {x.at("yield_J"), 1.0, "%.4g"},
              {x.at("depth_of_burst_m"), 1.0, "%.3g"},
              {x.at("scaled_depth_of_burst_m_per_kt3"), 1.0, "%.3g"}});
  expectLine(out,
             "coupling: the target holds " + number + "% of the yield \\(" + number +
                 "% kinetic, " + number + "% internal\\); the device keeps " + number + "%",
             {{x.at("target_share_of_yield"), 100.0, "%.1f"},
              {x.at("target_kinetic_fraction"), 100.0, "%.1f"},
              {x.at("target_internal_fraction"), 100.0, "%.1f"},
              {x.at("explosive_share_of_yield"), 100.0, "%.1f"}});
  std::string gauge = "gauge g1: peak " + number + " MPa at " + number + " ms";
  std::vector<Printed> gaugeValues = {{x.at("gauge_g1_peak_pressure_Pa"), 1e-6, "%.4g"},
                                      {x.at("gauge_g1_peak_time_s"), 1e3, "%.4g"}};
  if (x.contains("gauge_g1_decay_time_s")) {
    gauge += ", decay constant " + number + " us";
    gaugeValues.push_back({x.at("gauge_g1_decay_time_s"), 1e6, "%.3g"});
    if (x.contains("gauge_g1_decay_fit_s")) {
      gauge += " \\(1/e; fit " + number + " us\\)";
      gaugeValues.push_back({x.at("gauge_g1_decay_fit_s"), 1e6, "%.3g"});
    }
  }
  expectLine(out, gauge, gaugeValues);
  fs::remove_all(dir);
}

TEST(RunSummaryPrinted, ThermalLinesAreTheOnesInSummaryJson) {
  const fs::path dir =
      fs::temp_directory_path() / ("ejecta_chain_run_thermal_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeTextFile(dir / "small_follower.toml", kStudy);
  ejecta::test::TinyImpact impact;
  impact.extra = "[fields]\ngrids = [\"density\", \"temperature\", \"fractions\"]\n"
                 "[thermal]\nstudy = \"small_follower.toml\"\ntimes = [\"30 us\", \"60 us\"]\n";
  writeTextFile(dir / "scene.toml", ejecta::test::tinyImpactScene(impact));
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " run " + (dir / "scene.toml").string() +
                           " --quiet --no-charts --threads 2 --out " + (dir / "out").string(),
                       out),
            0)
      << out;
  const nlohmann::json j = nlohmann::json::parse(readTextFile(dir / "out" / "summary.json"));
  const nlohmann::json& x = j.at("extras");
  const std::string number = "([-+0-9.e]+|nan|inf)";
  expectLine(out,
             "spacecraft: the hottest of " + number + " pass\\(es\\), over the rock of t = " +
                 number + " ms \\(.*; up to " + number + " hot particles -> " + number +
                 " emitters\\)",
             {{x.at("thermal_passes"), 1.0, "%.0f"},
              {x.at("thermal_time_s"), 1e3, "%.3g"},
              {x.at("thermal_hot_particles"), 1.0, "%.0f"},
              {x.at("thermal_emitters"), 1.0, "%.0f"}});
  std::stringstream faces(x.at("thermal_faces").get<std::string>());
  int rows = 0;
  for (std::string face; std::getline(faces, face, ',');) {
    const std::string k = "thermal_" + face;
    std::vector<Printed> values = {{x.at(k + "_peak_flux_W_m2"), 1.0, "%.3g"},
                                   {x.at(k + "_steady_K"), 1.0, "%.0f"}};
    std::string row = "^    " + face + " +" + number + " W/m\\^2 +" + number + " K";
    if (x.contains(k + "_structure_peak_K")) {
      row += " +" + number + " K";
      values.push_back({x.at(k + "_structure_peak_K"), 1.0, "%.0f"});
    }
    expectLine(out, row + "$", values);
    ++rows;
  }
  EXPECT_GT(rows, 1);
  EXPECT_NE(out.find("  shield: " + x.at("thermal_shield").get<std::string>() + "\n"),
            std::string::npos)
      << out;
  fs::remove_all(dir);
}

}  // namespace
