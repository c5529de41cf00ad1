// Extending a run at a restart (`ejecta run --restart DIR --set time.t_end=...`,
// sim/run/run.hpp restartChangeableKeys): the Sod tube run to 0.1 s and then extended to 0.2 s,
// and again to 0.25 s, ends bit for bit where the run straight to 0.25 s ends (the extension's
// outputs keep the run's cadence, so its steps are the straight run's steps); keys that would
// change the run midway, and an end not beyond the snapshot, are refused with the reason.
#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <filesystem>
#include <string>

#include "core/input_error.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/embedded_scenes.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta {
namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& tag) {
  return fs::temp_directory_path() / ("ejecta_extend_" + tag + "_" + std::to_string(::getpid()));
}

// Sod with 0.05 s snapshots to t_end (the shipped scene), on one thread: bits independent of the
// machine's cores.
RunOutcome runTo(const fs::path& dir, const std::string& tEnd) {
  fs::remove_all(dir);
  RunOptions options;
  options.outDir = dir.string();
  options.threads = 1;
  options.sceneSource = std::string(findEmbeddedScene("verification/sod_1d"));
  options.overrides = {"time.t_end=" + tEnd};
  return runScene(parseScene(options.sceneSource, "sod_1d.toml", options.overrides), options);
}

RunOutcome extend(const fs::path& dir, const std::string& tEnd) {
  RunOptions options;
  options.threads = 1;
  options.restartOverrides = {"time.t_end=" + tEnd};
  return restartRun(dir.string(), options);
}

ParticleSet lastParticles(const fs::path& dir, SnapshotInfo& info) {
  fs::path last;
  for (const auto& e : fs::directory_iterator(dir / "snapshots"))
    if (last.empty() || e.path().filename() > last.filename()) last = e.path();
  return readSnapshot(last.string(), info);
}

TEST(RestartExtend, AnExtendedRunEndsBitForBitWhereTheStraightRunEnds) {
  const fs::path straight = tempDir("straight"), extended = tempDir("extended");
  ASSERT_TRUE(runTo(straight, "0.25 s").ok);
  ASSERT_TRUE(runTo(extended, "0.1 s").ok);
  const RunOutcome first = extend(extended, "0.2 s");
  ASSERT_TRUE(first.ok) << first.error;
  EXPECT_DOUBLE_EQ(first.summary.tEnd, 0.2);
  // Extended twice: the second restart sees snapshots of both lengths as one run.
  const RunOutcome second = extend(extended, "0.25 s");
  ASSERT_TRUE(second.ok) << second.error;

  SnapshotInfo a, b;
  const ParticleSet p = lastParticles(straight, a);
  const ParticleSet q = lastParticles(extended, b);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.time), std::bit_cast<std::uint64_t>(b.time));
  EXPECT_EQ(a.snapshotIndex, b.snapshotIndex);  // the same outputs: 0, 0.05, ..., 0.25 s
  ASSERT_EQ(p.numReal, q.numReal);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(p.x[0][i]), std::bit_cast<std::uint64_t>(q.x[0][i])) << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(p.rho[i]), std::bit_cast<std::uint64_t>(q.rho[i])) << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(p.u[i]), std::bit_cast<std::uint64_t>(q.u[i])) << i;
  }
  // The snapshot count: 0 .. 0.25 s every 0.05 s, no duplicate at the old ends.
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(extended / "snapshots")) files += e.path().extension() == ".h5";
  EXPECT_EQ(files, 6u);
  EXPECT_GE(second.summary.totalWallSeconds, 0.0);
  fs::remove_all(straight);
  fs::remove_all(extended);
}

TEST(RestartExtend, KeysThatWouldChangeTheRunMidwayAreRefused) {
  const fs::path dir = tempDir("refused");
  ASSERT_TRUE(runTo(dir, "0.05 s").ok);
  RunOptions options;
  options.threads = 1;
  options.restartOverrides = {"sph.kernel=wendland_c2"};
  try {
    restartRun(dir.string(), options);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'sph.kernel' cannot change at a restart"), std::string::npos) << what;
    EXPECT_NE(what.find("time.t_end"), std::string::npos) << what;
  }
  options.restartOverrides = {"time.max_steps=3"};
  try {
    restartRun(dir.string(), options);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("time.max_steps = 3 is not beyond"), std::string::npos) << e.what();
  }
  options.restartOverrides = {"time.t_end=0.05 s"};
  try {
    restartRun(dir.string(), options);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is not beyond the last snapshot"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(RestartExtend, TheSummaryCountsTheWholeCommand) {
  const fs::path dir = tempDir("wall");
  const RunOutcome r = runTo(dir, "0.05 s");
  ASSERT_TRUE(r.ok);
  EXPECT_GT(r.summary.totalWallSeconds, 0.0);
  EXPECT_GE(r.summary.totalWallSeconds, r.summary.wallSeconds);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ejecta
