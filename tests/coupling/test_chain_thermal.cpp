// The whole chain through the command line: `ejecta run` on a small RZ impact whose scene has a
// [thermal] table runs the radiation study in-situ at two output times, with the asteroid's
// surface from the output's grid file as occluder, and `ejecta thermal` on the run's snapshot of
// the same time gives the same flux (both paths build the same emitters from the same particles
// and the same occluder from the same grid file). Also the physics a pass must show (the face looking at
// the crater sees the most; eq. 4.8 holds between a face's flux and its temperature), the
// summary's fields, and clear errors for a [thermal] the run cannot serve.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "radiation/constants.hpp"
#include "render/charts.hpp"
#include "support/command_line.hpp"
#include "support/small_follower_study.hpp"
#include "support/tiny_impact.hpp"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::runCommand;
using ejecta::test::readTextFile;
using ejecta::test::writeTextFile;

// The small follower study (tests/support/small_follower_study.hpp).
const char* const kStudy = ejecta::test::kSmallFollowerStudy;

const Json* patch(const Json& thermal, const std::string& name) {
  for (const Json& p : thermal["patches"])
    if (p["patch"] == name) return &p;
  return nullptr;
}

// One run serves every check: a run takes ~10 s, and CTest starts each test in its own process.
TEST(ChainThermal, InSituPassesMatchTheCommandAndThePhysics) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_chain_thermal_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeTextFile(dir / "small_follower.toml", kStudy);
  ejecta::test::TinyImpact o;
  // Grids at every output: the asteroid's surface (their level set) occludes in both paths.
  o.extra = "[fields]\ngrids = [\"density\", \"temperature\", \"fractions\"]\n"
            "[thermal]\nstudy = \"small_follower.toml\"\ntimes = [\"30 us\", \"60 us\"]\n";
  writeTextFile(dir / "scene.toml", ejecta::test::tinyImpactScene(o));
  std::string output;
  ASSERT_EQ(runCommand(kEjecta + " run " + (dir / "scene.toml").string() + " --quiet --no-charts --threads 2 --out " +
                    (dir / "run").string(),
                output),
            0)
      << output;

  // One pass per requested time: snapshots at 0, 30 and 60 us, so outputs 1 and 2.
  for (const char* pass : {"thermal_0001", "thermal_0002"}) {
    const fs::path d = dir / "run" / pass;
    for (const char* file : {"thermal.json", "flux.csv", "wall_side0.csv", "sizing.csv"})
      EXPECT_TRUE(fs::exists(d / file)) << d / file;
  }
  EXPECT_FALSE(fs::exists(dir / "run" / "thermal_0000"));
  const Json summary = Json::parse(readTextFile(dir / "run" / "summary.json"));
  const Json& x = summary["extras"];
  EXPECT_EQ(x["thermal_passes"], 2);
  ASSERT_TRUE(x.contains("thermal_side0_steady_K")) << x.dump(1);
  EXPECT_TRUE(x.contains("thermal_shield_tungsten_mm"));
  EXPECT_TRUE(x.contains("thermal_shield"));
  EXPECT_NE(output.find("spacecraft: the hottest of 2"), std::string::npos) << output;

  // The physics of a pass.
  const Json t = Json::parse(readTextFile(dir / "run" / "thermal_0002" / "thermal.json"));
  ASSERT_GT(t["emitters"].get<int>(), 0) << "no material above the study's threshold";
  ASSERT_TRUE(t["occluder"].is_object()) << t["occluder"];
  EXPECT_GT(t["occluder"]["triangles"].get<int>(), 100);
  const Json* side0 = patch(t, "side0");
  const Json* aft = patch(t, "aft");
  ASSERT_TRUE(side0 && aft);
  const double q0 = (*side0)["peak_flux_W_m2"], qAft = (*aft)["peak_flux_W_m2"];
  // side0 looks down into the crater, aft away from it: at least ten times less (the aft face
  // sees only hot particles thrown above the box, if any).
  EXPECT_GT(q0, 0.0);
  EXPECT_LT(qAft, 0.1 * q0);
  // Eq. 4.8 with no sink: eps sigma T^4 = alpha q, to the round-off of the printed digits.
  const double a = (*side0)["absorptivity"], e = (*side0)["emissivity"];
  const double T = (*side0)["steady_temperature_K"];
  EXPECT_NEAR(e * ejecta::radiation::kStefanBoltzmann * std::pow(T, 4), a * q0, 1e-8 * a * q0);

  // `ejecta thermal` on the snapshot of the same output: the same particles (stored in double
  // precision) and the same deterministic rays, so the same flux up to the printed digits.
  const fs::path again = dir / "again";
  ASSERT_EQ(runCommand(kEjecta + " thermal " + (dir / "small_follower.toml").string() + " --from " +
                    (dir / "run" / "snapshots" / "snap_0002.h5").string() + " --out " + again.string(),
                output),
            0)
      << output;
  const Json fromFile = Json::parse(readTextFile(again / "thermal.json"));
  EXPECT_EQ(t["emitters"], fromFile["emitters"]);
  EXPECT_EQ(t["occluder"]["triangles"], fromFile["occluder"]["triangles"]);
  for (const Json& p : t["patches"]) {
    const Json* q = patch(fromFile, p["patch"]);
    ASSERT_TRUE(q) << p["patch"];
    const double inSitu = p["peak_flux_W_m2"], fromSnapshot = (*q)["peak_flux_W_m2"];
    EXPECT_NEAR(inSitu, fromSnapshot, 1e-9 * std::max(1.0, std::abs(inSitu))) << p["patch"];
  }
  // The sizing table pivoted for its chart (coupling/thermal_charts.hpp): side0's tungsten row in mm,
  // the same number sizing.csv gives in m ("nan" where the coating cannot protect the face).
  auto side0Row = [](const std::string& csv) {
    std::stringstream row(csv.substr(csv.find("\nside0,") + 1));
    std::string line;
    std::getline(row, line);
    std::vector<std::string> cells;
    std::stringstream split(line);
    for (std::string c; std::getline(split, c, ',');) cells.push_back(c);
    return cells;
  };
  const std::string pivot = readTextFile(again / "sizing_chart.csv");
  ASSERT_EQ(pivot.rfind("patch,tungsten_mm,tungsten_kg\n", 0), 0u) << pivot;
  const std::vector<std::string> sized = side0Row(readTextFile(again / "sizing.csv"));
  const std::vector<std::string> pivoted = side0Row(pivot);
  ASSERT_GE(sized.size(), 6u);
  ASSERT_EQ(pivoted.size(), 3u) << pivot;
  if (sized[3] == "1") {
    EXPECT_NEAR(std::stod(pivoted[1]), std::stod(sized[4]) * 1e3, 1e-6) << pivot;
  } else {
    EXPECT_EQ(pivoted[1], "nan") << pivot;
  }
  if (ejecta::render::ChartRunner().chartsAvailable()) {
    for (const char* png : {"flux.png", "wall_side0.png", "sizing.png"})
      EXPECT_TRUE(fs::exists(again / png)) << again / png;
  }

  // The same output's grid file as voxel emitters: a run's fraction grids (written "capped")
  // give each hot voxel its filled fraction, so the voxels hold about the hot particles' volume
  // (each particle's kernel integrates to 1: the integral of S over space is sum_j V_j). Counted
  // as full voxels they held 4.5 times it on impact_rz, and the flux doubled (docs/thermal.md).
  const fs::path voxels = dir / "voxels";
  ASSERT_EQ(runCommand(kEjecta + " thermal " + (dir / "small_follower.toml").string() + " --from " +
                    (dir / "run" / "snapshots" / "snap_0002.h5").string() + " --emitters voxels --no-charts --out " +
                    voxels.string(),
                output),
            0)
      << output;
  const Json fromVoxels = Json::parse(readTextFile(voxels / "thermal.json"));
  EXPECT_EQ(fromVoxels["grid_file"]["fill_weighted"], true) << fromVoxels["grid_file"];
  const double particleVolume = fromFile["emitter_volume_m3"], voxelVolume = fromVoxels["emitter_volume_m3"];
  ASSERT_GT(particleVolume, 0.0);
  // Measured 1.09 here; hot voxels reach up to a smoothing length beyond the hot
  // particles (the kernel's support), with their share of the neighbours' volume: within 2x.
  EXPECT_GT(voxelVolume, 0.5 * particleVolume);
  EXPECT_LT(voxelVolume, 2.0 * particleVolume);
  fs::remove_all(dir);
}

// The flux.csv rows of a pass: per sample time, the columns as numbers.
std::vector<std::vector<double>> fluxRows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) row.push_back(std::stod(c));
    rows.push_back(row);
  }
  return rows;
}

// An evolving pass sees at each sample time the material of that moment. Its first and last
// samples fall on outputs (the run lands on them), where a frozen pass over that output's
// material, at the same pose, must give the same flux: the pass from 30 us samples at 30, 45 and
// 60 us; the frozen pass of 30 us matches its first row, the frozen pass of 60 us its last.
TEST(ChainThermal, EvolvingPassSeesTheMaterialOfEachMoment) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_chain_evolving_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::string study = kStudy;
  study.replace(study.find("duration = \"1 ms\""), 17, "duration = \"30 us\"");
  writeTextFile(dir / "short_pass.toml", study);
  std::string output;
  for (const std::string mode : {"snapshot", "evolving"}) {
    ejecta::test::TinyImpact o;
    o.extra = "[thermal]\nstudy = \"short_pass.toml\"\nhot_material = \"" + mode + "\"\n" +
              (mode == "snapshot" ? "times = [\"30 us\", \"60 us\"]\n" : "times = [\"30 us\"]\n");
    writeTextFile(dir / (mode + ".toml"), ejecta::test::tinyImpactScene(o));
    ASSERT_EQ(runCommand(kEjecta + " run " + (dir / (mode + ".toml")).string() +
                      " --quiet --no-charts --threads 2 --out " + (dir / mode).string(),
                  output),
              0)
        << output;
  }
  const auto evolving = fluxRows(dir / "evolving" / "thermal_from_0.03ms" / "flux.csv");
  const auto at30 = fluxRows(dir / "snapshot" / "thermal_0001" / "flux.csv");
  const auto at60 = fluxRows(dir / "snapshot" / "thermal_0002" / "flux.csv");
  ASSERT_EQ(evolving.size(), 3u);
  ASSERT_EQ(at30.size(), 3u);
  ASSERT_EQ(at60.size(), 3u);
  // Column 1 is side0's flux. Same material, pose and deterministic rays: equal to the printed
  // digits.
  EXPECT_NEAR(evolving[0][1], at30[0][1], 1e-9 * at30[0][1]);
  EXPECT_NEAR(evolving[2][1], at60[2][1], 1e-9 * at60[2][1]);
  // And the material does change over the pass: the frozen 30 us pass's last sample differs.
  EXPECT_GT(std::abs(evolving[2][1] - at30[2][1]), 1e-3 * at30[2][1]);
  const Json t = Json::parse(readTextFile(dir / "evolving" / "thermal_from_0.03ms" / "thermal.json"));
  EXPECT_EQ(t["hot_material"], "evolving");
  fs::remove_all(dir);
}

TEST(ChainThermalErrors, PlanarRunIsRefusedBeforeItStarts) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_chain_thermal_err_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  ejecta::test::TinyImpact o;
  o.dimension = "2d";
  o.extra = "[thermal]\nstudy = \"thermal/follower\"\n";
  writeTextFile(dir / "planar.toml", ejecta::test::tinyImpactScene(o));
  std::string out;
  EXPECT_NE(runCommand(kEjecta + " run " + (dir / "planar.toml").string() + " --quiet --out " + (dir / "p").string(), out), 0);
  EXPECT_NE(out.find("planar.toml"), std::string::npos) << out;
  EXPECT_NE(out.find("no 3D extent"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "p" / "summary.json"));

  o.dimension = "rz";
  o.extra = "[thermal]\nstudy = \"no_such_study.toml\"\n";
  writeTextFile(dir / "missing.toml", ejecta::test::tinyImpactScene(o));
  EXPECT_NE(runCommand(kEjecta + " run " + (dir / "missing.toml").string() + " --quiet --out " + (dir / "m").string(), out), 0);
  EXPECT_NE(out.find("key 'thermal.study'"), std::string::npos) << out;
  EXPECT_NE(out.find("no_such_study.toml"), std::string::npos) << out;
  fs::remove_all(dir);
}

}  // namespace
