// Charts: the spec's JSON (escaping, defaults, rejected specs), and, where /usr/bin/python3 has
// matplotlib, real charts from a CSV: a line chart with log axes and a reference curve, a bar
// chart, and the script's error for a missing column. Without matplotlib those are skipped.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "render/charts.hpp"
#include "render/png_io.hpp"

namespace ejecta::render {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() {
    std::random_device entropy;
    path_ = fs::temp_directory_path() / ("ejecta-render-charts-" + std::to_string(::getpid()) +
                                         "-" + std::to_string(entropy()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// One runner for the file: asking python whether matplotlib imports takes a second.
ChartRunner& charts() {
  static ChartRunner runner;
  return runner;
}

// Pixels that are not white: the plot drew something.
int inked(const Image& image) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgba8 c = image.at(x, y);
      if (c.r < 200 || c.g < 200 || c.b < 200) ++n;
    }
  return n;
}

TEST(RenderCharts, SpecJsonIsEscapedAndComplete) {
  ChartSpec spec;
  spec.csv = "/data/energy.csv";
  spec.x = "time_s";
  spec.series.push_back({"kinetic_J", "kinetic \"KE\"\n", "", "", false, false});
  spec.series.push_back({"exact", "exact", "n", "/data/exact.csv", true, false});
  spec.ylog = true;
  spec.xlabel = "t [\xC2\xB5s]";
  spec.out = "/out/e.png";
  const std::string json = chartSpecJson(spec);
  EXPECT_NE(json.find(R"("label": "kinetic \"KE\"\n")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("csv": "/data/exact.csv")"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("reference": true)"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("ylog": true)"), std::string::npos) << json;
  EXPECT_NE(json.find(R"("xlog": false)"), std::string::npos) << json;
  EXPECT_NE(json.find("\"t [\xC2\xB5s]\""), std::string::npos) << json;
  EXPECT_NE(json.find(R"("kind": "line")"), std::string::npos) << json;
  // Relative paths become absolute, so the script can run from its temporary directory.
  spec.out = "relative.png";
  EXPECT_NE(chartSpecJson(spec).find(fs::absolute("relative.png").string()), std::string::npos);

  ChartSpec noSeries = spec;
  noSeries.series.clear();
  EXPECT_THROW(chartSpecJson(noSeries), std::invalid_argument);
  ChartSpec noOut = spec;
  noOut.out.clear();
  EXPECT_THROW(chartSpecJson(noOut), std::invalid_argument);
  ChartSpec noCsv = spec;
  noCsv.csv.clear();
  try {
    chartSpecJson(noCsv);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'kinetic_J' has no 'csv'"), std::string::npos);
  }
}

TEST(RenderCharts, LineChartWithLogAxesAndAReferenceCurve) {
  if (!charts().chartsAvailable()) GTEST_SKIP() << charts().unavailableReason();
  TempDir dir;
  // An error-vs-resolution study: second-order errors and the exact h^2 line.
  {
    std::ofstream csv(dir.path() / "convergence.csv");
    csv << "# a comment line\nresolution,error,second_order\n";
    for (int n : {16, 32, 64, 128, 256})
      csv << n << "," << 3.0 / (n * n) * (1.0 + 0.1 * std::sin(n)) << "," << 3.0 / (n * n) << "\n";
  }
  ChartSpec spec;
  spec.csv = dir.path() / "convergence.csv";
  spec.x = "resolution";
  spec.series = {{"error", "L1 error", "", "", false, true},
                 {"second_order", "h^2", "", "", true, false}};
  spec.xlog = spec.ylog = true;
  spec.xlabel = "particles per radius";
  spec.ylabel = "L1 error [m/s]";
  spec.title = "Sedov: error vs resolution";
  spec.out = dir.path() / "convergence.png";
  spec.width = 640;
  spec.height = 480;
  charts().writeChart(spec);
  const Image image = readPng(spec.out);
  EXPECT_EQ(image.width(), 640);
  EXPECT_EQ(image.height(), 480);
  EXPECT_GT(inked(image), 2000);           // axes, text, two curves
  EXPECT_LT(inked(image), 640 * 480 / 3);  // ...on a white background
  for (const auto& entry : fs::directory_iterator(dir.path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
        << "temporary file left: " << entry.path();
}

TEST(RenderCharts, BarChartOfCategories) {
  if (!charts().chartsAvailable()) GTEST_SKIP() << charts().unavailableReason();
  TempDir dir;
  {
    std::ofstream csv(dir.path() / "sizing.csv");
    csv << "design,areal_mass_kg_m2,peak_temperature_K\n"
        << "aluminium 2 mm,5.4,612\nwhipple 1+3 mm,10.8,455\nnextel-kevlar,7.1,498\n";
  }
  ChartSpec spec;
  spec.kind = ChartKind::Bar;
  spec.csv = dir.path() / "sizing.csv";
  spec.x = "design";
  spec.series = {{"areal_mass_kg_m2", "areal mass [kg/m^2]", "", "", false, false}};
  spec.out = dir.path() / "sizing.png";
  charts().writeChart(spec);
  const Image image = readPng(spec.out);
  EXPECT_EQ(image.width(), 900);
  EXPECT_EQ(image.height(), 600);
  EXPECT_GT(inked(image), 10000);  // three filled bars
}

TEST(RenderCharts, ScriptErrorsNameTheFileAndColumn) {
  if (!charts().chartsAvailable()) GTEST_SKIP() << charts().unavailableReason();
  TempDir dir;
  std::ofstream(dir.path() / "energy.csv") << "time_s,kinetic_J\n0,1\n1,0.5\n";
  ChartSpec spec;
  spec.csv = dir.path() / "energy.csv";
  spec.x = "time_s";
  spec.series = {{"internal_J", "", "", "", false, false}};
  spec.out = dir.path() / "energy.png";
  try {
    charts().writeChart(spec);
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("energy.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("'internal_J'"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(spec.out));
}

TEST(RenderCharts, MissingPythonIsReportedNotFatal) {
  ChartRunner none("/nonexistent/python3");
  EXPECT_FALSE(none.chartsAvailable());
  EXPECT_NE(none.unavailableReason().find("/nonexistent/python3"), std::string::npos);
  ChartSpec spec;
  spec.csv = "a.csv";
  spec.x = "x";
  spec.series = {{"y", "", "", "", false, false}};
  spec.out = "never.png";
  EXPECT_THROW(none.writeChart(spec), std::runtime_error);
}

}  // namespace
}  // namespace ejecta::render
