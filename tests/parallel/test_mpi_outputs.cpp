// A distributed run's files (CTest runs this binary under mpirun -np 2 and -np 3): snapshots in
// today's layout (one file per output, every particle, written by the ranks in turn), the XDMF series, energy.csv,
// gauges.csv and summary.json, all as a one-rank run writes them to the tolerance of
// test_mpi_runs.cpp; and a restart on one rank fewer than the run that wrote the snapshot.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <regex>
#include <fstream>
#include <sstream>

#include "parallel/mpi_support.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/run/physics_package.hpp"
#include "sim/run/run.hpp"
#include "support/periodic_blast.hpp"

namespace fs = std::filesystem;

namespace ejecta::test {
namespace {

constexpr double kTolerance = 1e-9;  // as test_mpi_runs.cpp, which says why

std::shared_ptr<const Communicator> world() { return worldCommunicator(); }
void barrier() { world()->sum(0); }

const std::string& sceneSource() {
  static const std::string source = periodicBlastScene() + R"(
[[gauges]]
name = "centre"
position = [0.0, 0.0]
[[gauges]]
name = "off_axis"
position = [0.21, -0.13]
)";
  return source;
}

RunOutcome runInto(const fs::path& dir, std::shared_ptr<const Communicator> ranks) {
  RunOptions options;
  options.outDir = dir.string();
  options.sceneSource = sceneSource();
  options.threads = 1;
  options.ranks = std::move(ranks);
  return runScene(parseScene(sceneSource(), "test_blast.toml"), options);
}

// As stored: the failed run's last snapshot holds its NaN on purpose.
ParticleSet snapshotById(const fs::path& file) {
  SnapshotInfo info;
  ParticleSet p = readSnapshot(file.string(), info, SnapshotValues::AsStored);
  sortById(p);
  return p;
}

std::vector<std::vector<double>> csvRows(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// Column by column, the largest difference over the column's largest magnitude.
double csvDifference(const fs::path& a, const fs::path& b) {
  const auto x = csvRows(a), y = csvRows(b);
  EXPECT_EQ(x.size(), y.size()) << a;
  if (x.size() != y.size() || x.empty()) return 1.0;
  double worst = 0.0;
  for (std::size_t c = 0; c < x[0].size(); ++c) {
    double scale = 0.0, diff = 0.0;
    for (std::size_t r = 0; r < x.size(); ++r) {
      scale = std::max(scale, std::abs(x[r][c]));
      diff = std::max(diff, std::abs(x[r][c] - y[r][c]));
    }
    // relative_error is itself a difference of nearly equal totals: judge it absolutely.
    worst = std::max(worst, scale > 1.0 ? diff / scale : diff);
  }
  return worst;
}

nlohmann::json summary(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  return nlohmann::json::parse(in);
}

class MpiOutputs : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::path(EJECTA_BINARY_DIR) / ("mpi_outputs_np" + std::to_string(world()->size()));
    if (world()->isRoot()) {
      fs::remove_all(root_);
      const RunOutcome serial = runInto(root_ / "one_rank", nullptr);
      ASSERT_TRUE(serial.ok) << serial.error;
    }
    barrier();
  }
  fs::path root_;
};

TEST_F(MpiOutputs, FilesMatchAOneRankRun) {
  const RunOutcome r = runInto(root_ / "ranks", world());
  EXPECT_TRUE(r.ok) << r.error;
  barrier();
  if (!world()->isRoot()) return;
  const fs::path one = root_ / "one_rank", many = root_ / "ranks";
  for (int k = 0; k <= 4; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "snap_%04d.h5", k);
    const ParticleSet a = snapshotById(one / "snapshots" / name);
    const ParticleSet b = snapshotById(many / "snapshots" / name);
    // (Rows are in rank order, as the ranks wrote them; compareParticles matches ids, and
    // fails unless both files hold the same particles once each.)
    const FieldDifference d = compareParticles(a, b);
    EXPECT_LE(d.relative, kTolerance) << name << ": " << d.field;
  }
  EXPECT_LE(csvDifference(one / "energy.csv", many / "energy.csv"), kTolerance);
  EXPECT_LE(csvDifference(one / "gauges.csv", many / "gauges.csv"), kTolerance);
  EXPECT_TRUE(fs::exists(many / "snapshots.xdmf"));
  const nlohmann::json s1 = summary(one), s2 = summary(many);
  EXPECT_EQ(s1["particles"], s2["particles"]);
  EXPECT_EQ(s1["steps"], s2["steps"]);
  EXPECT_EQ(s2["status"], "completed");
  EXPECT_EQ(s2["ranks"], world()->size());
  EXPECT_FALSE(s1.contains("ranks"));
}

TEST_F(MpiOutputs, RestartOnOneRankFewerMatchesAnUninterruptedRun) {
  const fs::path cut = root_ / "cut";
  const RunOutcome r = runInto(cut, world());
  EXPECT_TRUE(r.ok) << r.error;
  barrier();
  if (world()->isRoot()) {
    ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0003.h5"));
    ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0004.h5"));
  }
  barrier();
  // Ranks 0 .. size - 2 resume it (on 2 ranks: one rank resumes a 2-rank run's snapshot).
  const bool resumes = world()->rank() < world()->size() - 1;
  const auto part = world()->split(resumes ? 0 : 1);
  if (resumes) {
    RunOptions options;
    options.threads = 1;
    options.ranks = part;
    const RunOutcome resumed = restartRun(cut.string(), options);
    EXPECT_TRUE(resumed.ok) << resumed.error;
  }
  barrier();
  if (!world()->isRoot()) return;
  const FieldDifference d = compareParticles(snapshotById(root_ / "one_rank" / "snapshots" / "snap_0004.h5"),
                                             snapshotById(cut / "snapshots" / "snap_0004.h5"));
  EXPECT_LE(d.relative, kTolerance) << d.field;
  EXPECT_LE(csvDifference(root_ / "one_rank" / "energy.csv", cut / "energy.csv"), kTolerance);
  // The series lists every particle of every snapshot, the one resumed from (read in slices)
  // included.
  std::ifstream xdmf(cut / "snapshots.xdmf");
  std::stringstream text;
  text << xdmf.rdbuf();
  const std::string series = text.str();
  const std::regex dimensions(R"(Dimensions="(\d+))");
  int entries = 0;
  for (auto it = std::sregex_iterator(series.begin(), series.end(), dimensions);
       it != std::sregex_iterator(); ++it, ++entries)
    EXPECT_EQ((*it)[1].str(), "1600");
  EXPECT_GT(entries, 0);
  std::printf("[ ranks %d, resumed on %d ] snapshot 4: worst field %s differs by %.2e\n",
              world()->size(), world()->size() - 1, d.field.c_str(), d.relative);
}

// Individual time steps (docs/time_steps.md): a run on every rank, cut at its snapshot 2 and
// resumed on one rank fewer, ends as the uninterrupted one-rank run does (each particle's bin,
// own step and last evaluation are in the snapshots).
TEST(MpiIndividualSteps, RestartOnOneRankFewerMatchesAnUninterruptedOneRankRun) {
  std::string source = sceneSource();
  const std::string key = "t_end = 0.02\n";
  source.replace(source.find(key), key.size(), key + "stepping = \"individual\"\n");
  const fs::path root = fs::path(EJECTA_BINARY_DIR) /
                        ("mpi_individual_steps_np" + std::to_string(world()->size()));
  auto runInto = [&](const fs::path& dir, std::shared_ptr<const Communicator> ranks) {
    RunOptions options;
    options.outDir = dir.string();
    options.sceneSource = source;
    options.threads = 1;
    options.ranks = std::move(ranks);
    return runScene(parseScene(source, "test_blast.toml"), options);
  };
  if (world()->isRoot()) {
    fs::remove_all(root);
    const RunOutcome one = runInto(root / "one_rank", nullptr);
    ASSERT_TRUE(one.ok) << one.error;
  }
  barrier();
  const fs::path cut = root / "cut";
  const RunOutcome r = runInto(cut, world());
  EXPECT_TRUE(r.ok) << r.error;
  barrier();
  if (world()->isRoot()) {
    ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0003.h5"));
    ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0004.h5"));
  }
  barrier();
  const bool resumes = world()->rank() < world()->size() - 1;
  const auto part = world()->split(resumes ? 0 : 1);
  if (resumes) {
    RunOptions options;
    options.threads = 1;
    options.ranks = part;
    const RunOutcome resumed = restartRun(cut.string(), options);
    EXPECT_TRUE(resumed.ok) << resumed.error;
  }
  barrier();
  if (!world()->isRoot()) return;
  const FieldDifference d = compareParticles(snapshotById(root / "one_rank" / "snapshots" / "snap_0004.h5"),
                                             snapshotById(cut / "snapshots" / "snap_0004.h5"));
  EXPECT_LE(d.relative, kTolerance) << d.field;
  EXPECT_EQ(summary(root / "one_rank")["steps"], summary(cut)["steps"]);
  std::printf("[ ranks %d, resumed on %d ] individual steps, snapshot 4: worst field %s differs "
              "by %.2e\n", world()->size(), world()->size() - 1, d.field.c_str(), d.relative);
}

// Poisons one particle (by id) at the end of a step once the run passes `time`: a bad state that
// only the rank holding the particle can see.
class PoisonOneParticle : public PhysicsPackage {
 public:
  PoisonOneParticle(std::int64_t id, double time) : id_(id), time_(time) {}
  std::string name() const override { return "poison"; }
  void registerFields(ParticleSet&) override {}
  void finalize(ParticleSet& p, const PackageContext& c) override {
    if (c.time < time_) return;
    for (std::size_t i = 0; i < p.numReal; ++i)
      if (p.id[i] == id_) p.u[i] = std::nan("");
  }

 private:
  std::int64_t id_;
  double time_;
};

TEST_F(MpiOutputs, ABadStateOnOneRankStopsEveryRankWithItsDiagnosisAndALastSnapshot) {
  const fs::path dir = root_ / "failed";
  RunOptions options;
  options.outDir = dir.string();
  options.sceneSource = sceneSource();
  options.threads = 1;
  options.ranks = world();
  options.packages = {std::make_shared<PoisonOneParticle>(1234, 0.006)};
  const RunOutcome r = runScene(parseScene(sceneSource(), "test_blast.toml"), options);
  // Every rank stops, with the same message, naming the particle wherever it was.
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("non-finite state"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("particle id 1234 "), std::string::npos) << r.error;
  EXPECT_EQ(world()->firstMessage(world()->isRoot() ? r.error : std::string()), r.error);
  barrier();
  if (!world()->isRoot()) return;
  const nlohmann::json s = summary(dir);
  EXPECT_EQ(s["status"], "failed");
  EXPECT_EQ(s["message"], r.error);
  // The last snapshot holds the offending state, every rank's particles in it.
  const ParticleSet last = snapshotById(dir / "snapshots" / "snap_0002.h5");
  EXPECT_EQ(last.numReal, 1600u);
  EXPECT_TRUE(std::isnan(last.u[1234]));
}

}  // namespace
}  // namespace ejecta::test
