// A distributed run's in-situ outputs (CTest runs this binary under mpirun -np 2 and -np 3):
// the VDB grids and crater measurements made from grids that each rank splats from its own
// particles and rank 0 sums (fields/lattice_merge.hpp), and an evolving thermal pass whose
// every sample gathers only the hot particles, all as a one-rank run makes them; and the
// snapshot that the ranks write in turn into one file, with a failure on any rank reported by
// every rank and the earlier file left intact.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "coupling/run_thermal.hpp"
#include "fields/run_outputs.hpp"
#include "fields/vdb_grids.hpp"
#include "parallel/mpi_support.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/run/run.hpp"
#include "support/small_follower_study.hpp"
#include "support/tiny_impact.hpp"

namespace fs = std::filesystem;

namespace ejecta::test {
namespace {

std::shared_ptr<const Communicator> world() { return worldCommunicator(); }
void barrier() { world()->sum(0); }

// Grids are float32 sums whose order the ranks change (one rank: particle order; N ranks: each
// rank's partial sum, then the ranks in order): a voxel agrees to a few float ulps of the
// grid's largest value, 1e-5 with margin (the particle states themselves agree to 1e-9,
// test_mpi_runs.cpp). Crater figures come from rays marched through the sampled field, whose
// crossings move continuously with it: they agree to 3e-8 of each figure here, 1e-6 with margin.
constexpr double kGridTolerance = 1e-5;
constexpr double kCraterTolerance = 1e-6;
// The thermal pass sees the same hot particles (their temperatures agree to 1e-9, far from the
// threshold): fluxes and temperatures to the particles' agreement (1e-9; 1e-14 measured here).
constexpr double kThermalTolerance = 1e-8;

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
}

std::vector<std::vector<double>> csvRows(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && line.rfind('#', 0) == 0) {}  // comments, then the header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// The largest difference between two CSV files' cells, each relative to its column's largest
// magnitude (at least 1e-300); 1 when their shapes differ.
double csvDifference(const fs::path& a, const fs::path& b) {
  const auto x = csvRows(a), y = csvRows(b);
  if (x.empty() || x.size() != y.size()) return 1.0;
  double worst = 0.0;
  for (std::size_t c = 0; c < x[0].size(); ++c) {
    double scale = 1e-300, diff = 0.0;
    for (std::size_t r = 0; r < x.size(); ++r) {
      if (x[r].size() != y[r].size()) return 1.0;
      scale = std::max(scale, std::abs(x[r][c]));
      diff = std::max(diff, std::abs(x[r][c] - y[r][c]));
    }
    worst = std::max(worst, diff / scale);
  }
  return worst;
}

RunOutcome runInSitu(const fs::path& scene, const fs::path& out, std::shared_ptr<const Communicator> ranks) {
  RunOptions options;
  options.outDir = out.string();
  options.threads = 1;
  options.ranks = std::move(ranks);
  options.configure = [](const Scene& s, RunOptions& o) {
    fields::addFieldOutputs(o, s);
    coupling::addThermalOutputs(o, s, /*charts=*/false);
  };
  return runScene(loadScene(scene.string()), options);
}

class MpiInSitu : public ::testing::Test {
 protected:
  // Once for the suite: the scene, its study and the one-rank run (on rank 0).
  static void SetUpTestSuite() {
    dir_ = fs::path(EJECTA_BINARY_DIR) / ("mpi_in_situ_np" + std::to_string(world()->size()));
    if (world()->isRoot()) {
      fs::remove_all(dir_);
      fs::create_directories(dir_);
      // A pass from 30 us, sampled at 30, 45 and 60 us (the study's duration 30 us).
      std::string study = kSmallFollowerStudy;
      study.replace(study.find("duration = \"1 ms\""), 17, "duration = \"30 us\"");
      writeText(dir_ / "short_pass.toml", study);
      TinyImpact o;
      o.extra = "[fields]\ngrids = [\"density\", \"temperature\", \"fractions\"]\n"
                "[thermal]\nstudy = \"short_pass.toml\"\nhot_material = \"evolving\"\ntimes = [\"30 us\"]\n";
      writeText(dir_ / "scene.toml", tinyImpactScene(o));
      oneRankError_ = runInSitu(dir_ / "scene.toml", dir_ / "one_rank", nullptr).error;
    }
    barrier();
  }
  void SetUp() override { ASSERT_TRUE(oneRankError_.empty()) << oneRankError_; }
  static inline fs::path dir_;
  static inline std::string oneRankError_;
};

TEST_F(MpiInSitu, GridsCraterAndAnEvolvingThermalPassMatchAOneRankRun) {
  const RunOutcome r = runInSitu(dir_ / "scene.toml", dir_ / "ranks", world());
  EXPECT_TRUE(r.ok) << r.error;
  barrier();
  if (!world()->isRoot()) return;
  const fs::path one = dir_ / "one_rank", many = dir_ / "ranks";

  // Every grid of every output: the same voxel size (the median h, found exactly over the
  // ranks) and active voxels, and the same values at points across the crater.
  for (const char* file : {"fields_0000.vdb", "fields_0001.vdb", "fields_0002.vdb"}) {
    const std::string a = (one / "fields" / file).string(), b = (many / "fields" / file).string();
    ASSERT_TRUE(fs::exists(b)) << b;
    const std::vector<fields::StoredGrid> ga = fields::readGridFileInfo(a), gb = fields::readGridFileInfo(b);
    ASSERT_EQ(ga.size(), gb.size()) << file;
    for (std::size_t g = 0; g < ga.size(); ++g) {
      const std::string& name = ga[g].name;
      EXPECT_EQ(name, gb[g].name);
      EXPECT_EQ(ga[g].voxelSize, gb[g].voxelSize) << file << " " << name;
      EXPECT_EQ(ga[g].activeVoxels, gb[g].activeVoxels) << file << " " << name;
      const double scale = std::max({std::abs(ga[g].maxValue), std::abs(ga[g].minValue), 1e-30f});
      EXPECT_NEAR(ga[g].maxValue, gb[g].maxValue, kGridTolerance * scale) << file << " " << name;
      if (ga[g].gridClass == "level set") continue;  // its narrow band is checked by the crater
      double worst = 0.0;
      for (double x = -0.5; x <= 0.5; x += 0.1)
        for (double y = -0.3; y <= 0.1; y += 0.05) {
          const fields::Point at{x, y, 0.03};
          worst = std::max(worst, std::abs(fields::sampleGridFile(a, name, at) -
                                           fields::sampleGridFile(b, name, at)));
        }
      EXPECT_LE(worst, kGridTolerance * scale) << file << " " << name;
    }
  }
  // The crater at every output, from the merged target fraction.
  EXPECT_LE(csvDifference(one / "crater_history.csv", many / "crater_history.csv"), kCraterTolerance);
  EXPECT_LE(csvDifference(one / "crater_profile.csv", many / "crater_profile.csv"), kCraterTolerance);

  // The evolving pass: the same hot particles at each sample, so the same flux on every face.
  const fs::path pass = "thermal_from_0.03ms";
  ASSERT_TRUE(fs::exists(many / pass / "flux.csv"));
  ASSERT_EQ(csvRows(many / pass / "flux.csv").size(), 3u);
  EXPECT_LE(csvDifference(one / pass / "flux.csv", many / pass / "flux.csv"), kThermalTolerance);
  EXPECT_LE(csvDifference(one / pass / "wall_side0.csv", many / pass / "wall_side0.csv"), kThermalTolerance);
}

TEST_F(MpiInSitu, ASnapshotWrittenByTheRanksInTurnHoldsEveryParticleOnce) {
  const Scene scene = loadScene((dir_ / "scene.toml").string());
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet mine = buildParticles(scene, materials, world().get());
  const std::uint64_t total = world()->sum(mine.numReal);
  SnapshotInfo info;
  info.geometry = scene.geometry;
  info.time = 1.5e-5;
  const std::string path = (dir_ / "turns.h5").string();
  writeSnapshot(path, mine, info, *world());
  barrier();
  // Every rank reads the file whole: each of its own particles is there once, as it holds it.
  SnapshotInfo read;
  ParticleSet all = readSnapshot(path, read);
  EXPECT_EQ(all.numReal, total);
  EXPECT_EQ(read.time, info.time);
  std::vector<std::size_t> row(static_cast<std::size_t>(total), total);
  for (std::size_t i = 0; i < all.numReal; ++i) {
    ASSERT_LT(static_cast<std::uint64_t>(all.id[i]), total);
    EXPECT_EQ(row[static_cast<std::size_t>(all.id[i])], total) << "id " << all.id[i] << " twice";
    row[static_cast<std::size_t>(all.id[i])] = i;
  }
  for (std::size_t i = 0; i < mine.numReal; ++i) {
    const std::size_t at = row[static_cast<std::size_t>(mine.id[i])];
    ASSERT_LT(at, all.numReal);
    EXPECT_EQ(all.x[0][at], mine.x[0][i]);
    EXPECT_EQ(all.u[at], mine.u[i]);
    EXPECT_EQ(all.material[at], mine.material[i]);
  }
  barrier();

  // The last rank cannot write (its energy array is short): every rank reports it, naming the
  // rank, and the file written above is intact, with no temporary file left beside it.
  ParticleSet broken = mine;
  if (world()->rank() == world()->size() - 1) broken.u.resize(broken.numReal / 2);
  info.time = 3e-5;
  std::string error;
  try {
    writeSnapshot(path, broken, info, *world());
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("rank " + std::to_string(world()->size() - 1)), std::string::npos) << error;
  EXPECT_NE(error.find("turns.h5"), std::string::npos) << error;
  EXPECT_EQ(world()->firstMessage(world()->isRoot() ? error : std::string()), error);
  barrier();
  EXPECT_EQ(readSnapshotInfo(path).time, 1.5e-5);
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir_))
    if (entry.path().filename().string().find("turns") != std::string::npos) ++files;
  EXPECT_EQ(files, 1u);
}

}  // namespace
}  // namespace ejecta::test
