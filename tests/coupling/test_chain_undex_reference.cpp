// `ejecta undex-reference SCENE`: the converged 1D reference of a centred charge's gauges
// (apps/cmd_undex_reference.cpp over sim/verify/undex_reference.hpp, docs/undex.md), through the
// command line on tiny scenes: the CSV has the SPH gauges.csv layout and holds what the command
// prints, the gauges are placed by their distance from the charge, the geometry maps to the right
// symmetry, and scenes that are not a centred charge in one medium are refused with the file and
// the key.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "sim/exact/impedance_match.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/eos/mie_gruneisen.hpp"
#include "support/command_line.hpp"
#include "support/tiny_undex.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::readTextFile;
using ejecta::test::runCommand;
using ejecta::test::writeTextFile;

fs::path tempDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ejecta_chain_undex_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct Csv {
  std::vector<std::string> header;
  std::map<std::string, std::vector<double>> columns;
};

Csv readCsv(const fs::path& path) {
  Csv csv;
  std::stringstream in(readTextFile(path));
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) csv.header.push_back(c);
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::size_t k = 0;
    for (std::string c; std::getline(cells, c, ',') && k < csv.header.size(); ++k)
      csv.columns[csv.header[k]].push_back(
          std::strtod(c.c_str(), nullptr));  // stod refuses subnormals
  }
  return csv;
}

// A 1 kg TNT sphere (the undex_rz charge) in a 0.3 m quarter of water, to 0.1 ms: gauges on the
// axis at 0.1 m and 0.1414 m, and one on the diagonal at the same 0.1414 m.
const std::string kTinyRz = ejecta::test::tinyUndexRzScene(R"(
[[gauges]]
name = "g100"
position = ["0.1 m", 0.0]
[[gauges]]
name = "axis"
position = ["0.141421356 m", 0.0]
[[gauges]]
name = "diagonal"
position = ["0.1 m", "0.1 m"]
)");

TEST(UndexReference, SphericalChargeWritesTheGaugesAndColesValues) {
  const fs::path dir = tempDir("rz");
  writeTextFile(dir / "tiny.toml", kTinyRz);
  std::string out;
  // 300 zones of 1 mm: ~2,000 steps, well under a second.
  ASSERT_EQ(runCommand(kEjecta + " undex-reference " + (dir / "tiny.toml").string() +
                           " --zones 300 --out " + (dir / "out").string(),
                       out),
            0)
      << out;
  EXPECT_NE(out.find("spherical"), std::string::npos) << out;
  EXPECT_NE(out.find("0.9993 kg"), std::string::npos) << out;  // (4/3) pi 0.0527^3 1630
  EXPECT_NE(out.find("Cole peak"), std::string::npos) << out;
  const Csv csv = readCsv(dir / "out" / "gauges_reference.csv");
  // The SPH gauges.csv layout (sim/sources/gauges.hpp), RZ: two velocity axes per gauge.
  const std::vector<std::string> expected = {"step",
                                             "time_s",
                                             "g100_pressure_Pa",
                                             "g100_density_kg_m3",
                                             "g100_velocity_x_m_s",
                                             "g100_velocity_y_m_s"};
  ASSERT_GE(csv.header.size(), expected.size());
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), csv.header.begin()));
  EXPECT_EQ(csv.header.size(), 2u + 3u * 4u);
  const auto& time = csv.columns.at("time_s");
  ASSERT_GT(time.size(), 100u);
  EXPECT_DOUBLE_EQ(time.back(), 1e-4);
  EXPECT_DOUBLE_EQ(csv.columns.at("g100_pressure_Pa").front(), 101325.0);
  // The printed peak is the CSV's largest overpressure (every step is a row at this size).
  const auto& p = csv.columns.at("g100_pressure_Pa");
  const double peak = *std::max_element(p.begin(), p.end()) - 101325.0;
  std::istringstream lines(out);
  double printed = 0.0;
  for (std::string line; std::getline(lines, line);)
    if (line.find("  g100 ") == 0) printed = std::stod(line.substr(line.find("0.1") + 3));
  EXPECT_NEAR(printed, peak * 1e-6, 5e-4 * printed) << out;  // printed to 4 digits
  // A gauge is placed by its distance from the charge's centre: the diagonal one reads the axis
  // one at the same distance, with its velocity split equally between x and y.
  const auto& axis = csv.columns.at("axis_pressure_Pa");
  const auto& diagonal = csv.columns.at("diagonal_pressure_Pa");
  for (std::size_t k = 0; k < axis.size(); ++k)
    EXPECT_NEAR(diagonal[k], axis[k], 1e-6 * axis[k] + 1e-3);
  const auto& vx = csv.columns.at("diagonal_velocity_x_m_s");
  const auto& vy = csv.columns.at("diagonal_velocity_y_m_s");
  const auto& axisV = csv.columns.at("axis_velocity_x_m_s");
  const std::size_t mid = vx.size() / 2;
  EXPECT_GT(axisV[mid], 1.0);  // the shock (arriving at ~0.05 ms) has set the water moving
  EXPECT_NEAR(vx[mid], vy[mid], 1e-9 * std::abs(vx[mid]));
  EXPECT_NEAR(std::hypot(vx[mid], vy[mid]), axisV[mid], 1e-6 * axisV[mid]);
  fs::remove_all(dir);
}

TEST(UndexReference, SlabSceneAgainstTheImpedanceMatch) {
  // The 1D verification scene: a 100 mm TNT slab lit at its walled end, 60 mm of water. 800 zones
  // of 0.2 mm. The water shock at 4 mm must be below p* (the Taylor wave behind the C-J front
  // weakens it at once) and within 10% of it: measured 13.40 GPa, 0.921 p* (SPH at 0.2 mm: 13.00
  // GPa, docs/undex.md).
  const fs::path dir = tempDir("line");
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " undex-reference " + std::string(EJECTA_SOURCE_DIR) +
                           "/scenes/verification/undex_1d.toml --zones 800 --out " + dir.string(),
                       out),
            0)
      << out;
  EXPECT_NE(out.find("planar"), std::string::npos) << out;
  EXPECT_EQ(out.find("Cole"), std::string::npos) << out;
  const Csv csv = readCsv(dir / "gauges_reference.csv");
  const auto& p = csv.columns.at("w04_pressure_Pa");
  const double peak = *std::max_element(p.begin(), p.end());
  const double pStar = ejecta::exact::detonationImpedanceMatch(ejecta::jwlExplosive("TNT"),
                                                               ejecta::shockMaterial("water"))
                           .pressure();
  EXPECT_LT(peak, pStar);
  EXPECT_GT(peak, 0.9 * pStar) << peak;
  // The cylinder: the planar scene maps to j = 2.
  ASSERT_EQ(
      runCommand(kEjecta + " undex-reference " + std::string(EJECTA_SOURCE_DIR) +
                     "/scenes/undex_2d.toml --zones 200 --set 'time.t_end=\"0.05 ms\"' --out " +
                     dir.string(),
                 out),
      0)
      << out;
  EXPECT_NE(out.find("cylindrical"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(UndexReference, RefusesScenesThatAreNotACentredCharge) {
  const fs::path dir = tempDir("bad");
  auto refused = [&](const std::string& name, const std::string& from, const std::string& to,
                     const std::string& says) {
    std::string text = kTinyRz;
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    writeTextFile(dir / (name + ".toml"), text);
    std::string out;
    EXPECT_EQ(runCommand(kEjecta + " undex-reference " + (dir / (name + ".toml")).string() +
                             " --zones 50 --out " + dir.string(),
                         out),
              1)
        << out;
    EXPECT_NE(out.find(name + ".toml"), std::string::npos) << out;
    EXPECT_NE(out.find(says), std::string::npos) << out;
  };
  refused("offcentre", "center = [0.0, 0.0]", "center = [0.0, 0.02]", "key 'bodies[0].center'");
  refused("twodets", "[[gauges]]",
          "[[detonations]]\nname = \"second\"\nmaterial = \"tnt\"\npoint = [0.0, 0.01]\n[[gauges]]",
          "key 'detonations'");
  refused("openplane", "lower = \"wall\", ", "", "mirror wall");
  refused("moving", "pressure = \"101325 Pa\"", "pressure = \"101325 Pa\"\nvelocity = [0.0, 10.0]",
          "key 'bodies[1].velocity'");
  std::string out;
  EXPECT_EQ(runCommand(kEjecta + " undex-reference " + (dir / "missing.toml").string(), out), 1);
  EXPECT_NE(out.find("missing.toml"), std::string::npos) << out;
  fs::remove_all(dir);
}

}  // namespace
