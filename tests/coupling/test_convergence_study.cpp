// The convergence study's machinery (coupling/convergence_study, issue 23) on the Sod tube with a
// gauge: the levels' overrides scale every body's spacing, Gaussian deposits' widths and the
// --key values (their units kept); the study runs coarsest first, reads back levels already
// run, and names the numbers a summary has when a quantity is not among them.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
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

TEST(ConvergenceStudy, ARangeIsReadAsQuantityMinimumMaximum) {
  const auto [name, range] = parseQuantityRange("target_share_of_yield=0:1");
  EXPECT_EQ(name, "target_share_of_yield");
  EXPECT_EQ(range.minimum, 0.0);
  EXPECT_EQ(range.maximum, 1.0);
  // Either side may be left open.
  EXPECT_EQ(parseQuantityRange("crater_depth_m=0:").second.maximum, std::numeric_limits<double>::infinity());
  EXPECT_EQ(parseQuantityRange("x=:2.5e3").second.minimum, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(parseQuantityRange("x=:2.5e3").second.maximum, 2500.0);
  // Each malformed text is refused with what is wrong and the form expected.
  for (const char* bad : {"x", "=0:1", "x=0", "x=a:1", "x=0:1b", "x=1:0", "x=2:2", "x=0:inf", "x=nan:1"}) {
    try {
      parseQuantityRange(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(std::string("'") + bad + "'"), std::string::npos) << what;
      EXPECT_NE(what.find("QUANTITY=MIN:MAX"), std::string::npos) << what;
    }
  }
}

TEST(ConvergenceStudy, ABandIsClippedToTheQuantitysRange) {
  // The 1D Sedov blast's shock radius at four levels (a second's runs), first with no range: the
  // band is the finest value +- the uncertainty.
  ConvergenceOptions o;
  o.factors = {4.0, 2.0, std::sqrt(2.0), 1.0};
  o.quantities = {"shock_radius"};
  const ConvergenceResult open = runVerificationConvergence("sedov_1d", o);
  const QuantityConvergence& q = open.quantities.at(0);
  ASSERT_NE(q.convergence.basis, verify::UncertaintyBasis::None) << q.convergence.note;
  const double fine = open.levels.back().values.at("shock_radius"), band = q.convergence.uncertainty;
  ASSERT_GT(band, 0.0);
  EXPECT_EQ(q.bandLow, fine - band);
  EXPECT_EQ(q.bandHigh, fine + band);
  EXPECT_FALSE(q.bandClipped);
  // A range that cuts the band's lower half (as a share's 0% cuts a band wider than the share):
  // that side stops at it, the other is kept, and the band says it was clipped. The
  // uncertainty itself is the study's, unchanged.
  o.ranges["shock_radius"] = {.minimum = fine - 0.5 * band};
  const ConvergenceResult cut = runVerificationConvergence("sedov_1d", o);
  const QuantityConvergence& c = cut.quantities.at(0);
  EXPECT_EQ(c.convergence.uncertainty, band);
  EXPECT_EQ(c.bandLow, fine - 0.5 * band);
  EXPECT_EQ(c.bandHigh, fine + band);
  EXPECT_TRUE(c.bandClipped);
  // A range wider than the band changes nothing.
  o.ranges["shock_radius"] = {.minimum = 0.0, .maximum = 1.0};
  const QuantityConvergence wide = runVerificationConvergence("sedov_1d", o).quantities.at(0);
  EXPECT_EQ(wide.bandLow, fine - band);
  EXPECT_FALSE(wide.bandClipped);
  // A range that leaves out the finest value itself is not what the quantity can be: the band
  // stays whole and the note says why.
  o.ranges["shock_radius"] = {.minimum = fine + 0.5 * band};
  const QuantityConvergence wrong = runVerificationConvergence("sedov_1d", o).quantities.at(0);
  EXPECT_EQ(wrong.bandLow, fine - band);
  EXPECT_EQ(wrong.bandHigh, fine + band);
  EXPECT_FALSE(wrong.bandClipped);
  EXPECT_NE(wrong.convergence.note.find("lies outside --range"), std::string::npos) << wrong.convergence.note;
  // A range for a quantity the study does not collect, or an empty one, is refused before any
  // level runs.
  o.ranges = {{"no_such", {}}};
  EXPECT_THROW(runVerificationConvergence("sedov_1d", o), std::invalid_argument);
  o.ranges = {{"shock_radius", {.minimum = 1.0, .maximum = 0.5}}};
  EXPECT_THROW(runVerificationConvergence("sedov_1d", o), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::coupling
