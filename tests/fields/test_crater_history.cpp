// The crater's growth during an impact run (fields/crater_history, fields/run_outputs; issue 3):
// crater_history.csv gets one row per output, its last row is the summary's crater, the crater
// deepens while it is excavated, and a restart continues the history as if never interrupted.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "fields/crater_history.hpp"
#include "fields/run_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"
#include "tests/support/tiny_impact.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {
namespace {

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// The CSV as rows of numbers (header dropped).
std::vector<std::vector<double>> readNumbers(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) {
      double v = 0.0;
      std::from_chars(cell.data(), cell.data() + cell.size(), v);
      row.push_back(v);
    }
    rows.push_back(row);
  }
  return rows;
}

CraterMetrics someCrater(double depth) {
  CraterMetrics m;
  m.found = true;
  m.depth = depth;
  m.apparentDiameter = 0.1 + 3 * depth;
  m.rimDiameter = 0.2 + 3 * depth;
  m.rimHeight = 0.01;
  m.volume = 1.0 / 3.0;  // not a short decimal: the row must still read back exactly
  m.excavatedMass = 2680.0 / 3.0;
  m.elongation = 1.0;
  return m;
}

TEST(CraterHistory, RowsReadBackExactly) {
  EXPECT_EQ(craterHistoryHeader(false),
            "time_s,found,depth_m,apparent_diameter_m,rim_diameter_m,rim_height_m,volume_m3,"
            "excavated_mass_kg,elongation");
  EXPECT_EQ(craterHistoryHeader(true),
            "time_s,found,depth_m,apparent_diameter_m,rim_diameter_m,rim_height_m,area_m2,"
            "excavated_mass_kg_per_m");
  const CraterMetrics m = someCrater(0.123456789012345);
  const std::string row = craterHistoryRow(2.5e-5, m, false);
  std::vector<double> cells;
  std::stringstream s(row);
  for (std::string cell; std::getline(s, cell, ',');) {
    double v = 0.0;
    std::from_chars(cell.data(), cell.data() + cell.size(), v);
    cells.push_back(v);
  }
  ASSERT_EQ(cells.size(), 9u);
  EXPECT_EQ(cells[0], 2.5e-5);
  EXPECT_EQ(cells[1], 1.0);
  EXPECT_EQ(cells[2], m.depth);
  EXPECT_EQ(cells[6], m.volume);
  EXPECT_EQ(cells[7], m.excavatedMass);
  // Planar: an area and a mass per metre, no elongation.
  const std::string planar = craterHistoryRow(0.0, m, true);
  EXPECT_EQ(std::count(planar.begin(), planar.end(), ','), 7);
}

TEST(CraterHistory, FreshRunReplacesAnOldFileAndRestartKeepsEarlierRows) {
  const fs::path dir = freshDir("crater_history_unit");
  const fs::path file = dir / "crater_history.csv";
  // A fresh run (first output at t = 0) does not read what is there, even if it is not a history.
  writeText(file, "something else entirely\n1,2,3\n");
  {
    CraterHistory h(file, false);
    for (int i = 0; i < 4; ++i) h.record(1e-5 * i, someCrater(0.01 * i));
  }
  const std::string full = slurp(file);
  EXPECT_EQ(full.substr(0, full.find('\n')), craterHistoryHeader(false));
  EXPECT_EQ(std::count(full.begin(), full.end(), '\n'), 5);

  // A restart whose first output is at 2e-5 s: the rows at 0 and 1e-5 s are kept, those at and
  // after 2e-5 s (past the snapshot it resumed from) are replaced.
  {
    CraterHistory h(file, false);
    for (int i = 2; i < 4; ++i) h.record(1e-5 * i, someCrater(0.01 * i));
  }
  EXPECT_EQ(slurp(file), full);

  // Damaged files: named, with the line and the reason.
  writeText(file, craterHistoryHeader(true) + "\n0,0,0,0,0,0,0,0\n");
  try {
    CraterHistory(file, false).record(1e-5, someCrater(0.01));
    FAIL() << "a planar history read as a volumetric one";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":1:"), std::string::npos) << e.what();
  }
  writeText(file, craterHistoryHeader(false) + "\n0,0,0,0,0,0,0,0,1\nabc,1,0,0,0,0,0,0,1\n");
  try {
    CraterHistory(file, false).record(1e-5, someCrater(0.01));
    FAIL() << "a row with no time";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ":3: time_s"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// The tiny impact (a 0.1 m aluminium ball at 3 km/s on granite, RZ, ~1,500 particles), an
// output every 15 us to 60 us: rows at 0, 15, 30, 45, 60 us.
std::string tinyImpactSource() {
  test::TinyImpact o;
  o.snapshotInterval = "15 us";
  return test::tinyImpactScene(o);
}

RunOptions impactOptions(const fs::path& dir) {
  RunOptions options;
  options.outDir = dir.string();
  options.sceneSource = tinyImpactSource();  // stored in the snapshots, for the restart
  options.threads = 1;
  options.configure = [](const Scene& s, RunOptions& o) { addFieldOutputs(o, s); };
  return options;
}

TEST(CraterHistory, ImpactRunRecordsEveryOutputAndEndsWithTheSummary) {
  const fs::path dir = freshDir("crater_history_run");
  const RunOutcome r = runScene(parseScene(tinyImpactSource(), "tiny.toml"), impactOptions(dir));
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<std::vector<double>> rows = readNumbers(dir / "crater_history.csv");
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 9u);
    EXPECT_NEAR(rows[i][0], 15e-6 * static_cast<double>(i), 1e-12);
  }
  // t = 0: the ball is still 2 cm above the surface; no crater.
  EXPECT_EQ(rows[0][1], 0.0);
  // From the first output after contact (~7 us) there is one.
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i][1], 1.0) << "row " << i;
  // Excavation: 60 us is early in the crater's growth (the ball takes ~33 us just to cross its
  // own diameter at 3 km/s), before any rebound, so the cavity can only deepen. A resolution
  // (0.01 m, half the smoothing length) of slack would hide a real shallowing, so none is given.
  for (std::size_t i = 2; i < rows.size(); ++i)
    EXPECT_GE(rows[i][2], rows[i - 1][2]) << "depth fell between rows " << i - 1 << " and " << i;
  EXPECT_GT(rows.back()[2], rows[1][2] + 0.02);  // and grew by more than a spacing

  // The last row is the summary's crater, to the bit (both are the measurement at t_end).
  std::ifstream in(dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  const nlohmann::json& x = j["extras"];
  ASSERT_TRUE(x["crater_found"].get<bool>());
  const std::vector<double>& last = rows.back();
  EXPECT_EQ(last[0], j["t_end"].get<double>()) << j.dump(2);
  EXPECT_EQ(last[2], x["crater_depth_m"].get<double>());
  EXPECT_EQ(last[3], x["crater_apparent_diameter_m"].get<double>());
  EXPECT_EQ(last[4], x["crater_rim_diameter_m"].get<double>());
  EXPECT_EQ(last[5], x["crater_rim_height_m"].get<double>());
  EXPECT_EQ(last[6], x["crater_volume_m3"].get<double>());
  EXPECT_EQ(last[7], x["crater_excavated_mass_kg"].get<double>());
  EXPECT_EQ(last[8], x["crater_elongation"].get<double>());

  // A restart from the output at 30 us gives the same file, byte for byte: restarts are exact
  // (test_simulation), the rows before 30 us are kept and the later ones not repeated.
  const fs::path cut = freshDir("crater_history_cut");
  fs::copy(dir, cut, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0003.h5"));
  ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0004.h5"));
  RunOptions resume;
  resume.threads = 1;
  resume.configure = [](const Scene& s, RunOptions& o) { addFieldOutputs(o, s); };
  const RunOutcome resumed = restartRun(cut.string(), resume);
  ASSERT_TRUE(resumed.ok) << resumed.error;
  EXPECT_EQ(slurp(cut / "crater_history.csv"), slurp(dir / "crater_history.csv"));
  std::printf("crater history of the tiny impact:\n%s", slurp(dir / "crater_history.csv").c_str());
  fs::remove_all(dir);
  fs::remove_all(cut);
}

}  // namespace
}  // namespace ejecta::fields
