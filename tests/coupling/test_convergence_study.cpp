// The convergence study's machinery (coupling/convergence_study, issue 23) on the Sod tube with a
// gauge: the levels' overrides scale every body's spacing, Gaussian deposits' widths and the
// --key values (their units kept); the study runs coarsest first, reads back levels already
// run, and names the numbers a summary has when a quantity is not among them.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/input_error.hpp"
#include "coupling/convergence_study.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {
namespace {

std::string sodWithGauge() {
  std::ifstream in(std::string(EJECTA_SOURCE_DIR) + "/scenes/verification/sod_1d.toml");
  std::stringstream text;
  text << in.rdbuf();
  return text.str() + "\n[[gauges]]\nname = \"mid\"\nposition = [\"250 mm\"]\n";
}

bool has(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

TEST(ConvergenceStudy, ALevelScalesEveryLengthTiedToTheResolution) {
  ConvergenceOptions o;
  o.scaledKeys = {"gauges[0].position", "time.t_end"};
  o.overrides = {"sph.eta=1.3"};
  const std::vector<std::string> v = levelOverrides(sodWithGauge(), "sod.toml", o, 0.5);
  EXPECT_TRUE(has(v, "sph.eta=1.3")) << "the study's own --set comes first";
  EXPECT_TRUE(has(v, "bodies[0].spacing=0.000625"));
  EXPECT_TRUE(has(v, "bodies[1].spacing=0.005"));
  EXPECT_TRUE(has(v, "gauges[0].position=[\"125 mm\"]"));  // the unit kept
  EXPECT_TRUE(has(v, "time.t_end=\"0.1 s\""));
  ConvergenceOptions missing;
  missing.scaledKeys = {"fields.voxel"};
  EXPECT_THROW(levelOverrides(sodWithGauge(), "sod.toml", missing, 0.5), SceneError);
  ConvergenceOptions text;
  text.scaledKeys = {"scene.name"};
  EXPECT_THROW(levelOverrides(sodWithGauge(), "sod.toml", text, 0.5), SceneError);
}

TEST(ConvergenceStudy, RunsCoarsestFirstAndReadsBackWhatIsDone) {
  ConvergenceOptions o;
  o.factors = {1.0, 2.0, 1.5};
  o.quantities = {"gauge_mid_arrival_s", "energy_relative_error"};
  o.outDir = fs::temp_directory_path() / ("ejecta_converge_" + std::to_string(::getpid()));
  fs::remove_all(o.outDir);
  int ran = 0;
  o.onLevel = [&ran](double, std::size_t, double seconds) { ran += seconds >= 0.0; };
  const ConvergenceResult r = runConvergenceStudy(sodWithGauge(), "sod.toml", o);
  EXPECT_EQ(ran, 3);
  ASSERT_EQ(r.levels.size(), 3u);
  EXPECT_EQ(r.levels[0].factor, 2.0);
  EXPECT_EQ(r.levels[2].factor, 1.0);
  EXPECT_DOUBLE_EQ(r.levels[2].spacing, 0.00125);
  EXPECT_LT(r.levels[0].particles, r.levels[2].particles);
  // The shock reaches x = 0.25 at 0.1427 s (the exact Sod solution: shock speed 1.7522).
  EXPECT_NEAR(r.levels[2].values.at("gauge_mid_arrival_s"), 0.25 / 1.7522, 0.002);
  ASSERT_EQ(r.quantities.size(), 2u);
  const std::string csv = levelsCsv(r);
  EXPECT_NE(csv.find("factor,spacing_m,particles,wall_seconds,gauge_mid_arrival_s,energy_relative_error"),
            std::string::npos);
  // Each quantity's row says what its band rests on (bench/headline.py reads the same names).
  const std::string table = convergenceCsv(r);
  EXPECT_NE(table.find("quantity,finest,observed_order,extrapolated,gci,uncertainty,uncertainty_basis,band_order,"
                       "band_at_half_spread,asymptotic,oscillatory,ls_order,ls_standard_deviation,ls_uncertainty,note"),
            std::string::npos);
  for (const QuantityConvergence& q : r.quantities)
    EXPECT_NE(table.find(q.name + ","), std::string::npos);
  EXPECT_THROW(runConvergenceStudy(sodWithGauge(), "sod.toml", {.factors = {1.0}, .quantities = {"x"},
                                                                 .formalOrder = -1.0}),
               std::invalid_argument);
  // Again: nothing runs.
  ran = 0;
  const ConvergenceResult again = runConvergenceStudy(sodWithGauge(), "sod.toml", o);
  EXPECT_EQ(ran, 0);
  EXPECT_EQ(again.levels[2].values.at("gauge_mid_arrival_s"), r.levels[2].values.at("gauge_mid_arrival_s"));
  // A quantity the summaries lack: the error names the numbers they have.
  o.quantities = {"crater_depth_m"};
  try {
    runConvergenceStudy(sodWithGauge(), "sod.toml", o);
    FAIL() << "a missing quantity was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("its numbers: energy_relative_error, wall_seconds, particles, steps, "), std::string::npos)
        << what;
    EXPECT_NE(what.find("gauge_mid_peak_pressure_Pa"), std::string::npos) << what;
    EXPECT_NE(what.back(), ' ') << what;
  }
  // Summaries with no extras: the list is the fixed four, with no separator after the last.
  for (const fs::directory_entry& level : fs::directory_iterator(o.outDir)) {
    if (level.path().filename().string().rfind("level_", 0) != 0) continue;
    const fs::path summaryPath = level.path() / "summary.json";
    std::ifstream in(summaryPath);
    nlohmann::json summary = nlohmann::json::parse(in);
    in.close();
    summary["extras"] = nlohmann::json::object();
    std::ofstream(summaryPath) << summary.dump();
  }
  try {
    runConvergenceStudy(sodWithGauge(), "sod.toml", o);
    FAIL() << "a missing quantity was accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    const std::string fixed = "its numbers: energy_relative_error, wall_seconds, particles, steps";
    ASSERT_GE(what.size(), fixed.size()) << what;
    EXPECT_EQ(what.substr(what.size() - fixed.size()), fixed) << what;
  }
  o.factors = {1.0, 1.0};
  EXPECT_THROW(runConvergenceStudy(sodWithGauge(), "sod.toml", o), std::invalid_argument);
  fs::remove_all(o.outDir);
}

}  // namespace
}  // namespace ejecta::coupling
