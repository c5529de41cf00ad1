// Kill -9 at random moments of `ejecta run` (docs/robustness.md): whatever moment the process
// dies at, every file it left is either complete (a snapshot that reads and passes its checks) or
// a temporary that the restart removes, and a chain of restarts, each killed again, ends on
// the same particles, bit for bit, as the run never killed. The moments come from a fixed seed,
// so a failure reproduces.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/particle_difference.hpp"
#include "sim/io/snapshot.hpp"
#include "support/command_line.hpp"

namespace fs = std::filesystem;

namespace ejecta::test {
namespace {

// The corpus's base scene at 0.01 m (2,558 particles, ~4 s on one thread) with a snapshot every
// 20 us and grids at each: a kill lands in stepping, in a snapshot write or in a grid write.
const std::string kScene = " --quiet --no-charts --threads 1"
                           " --set 'bodies[0].spacing=0.01 m' --set 'bodies[1].spacing=0.01 m'"
                           " --set 'time.t_end=0.2 ms' --set 'output.snapshot_interval=0.02 ms'";
const std::string kBaseScene = std::string(EJECTA_SOURCE_DIR) + "/tests/hostile/base_scene.toml";

std::vector<fs::path> snapshotsIn(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::exists(dir / "snapshots")) return files;
  for (const auto& entry : fs::directory_iterator(dir / "snapshots"))
    if (entry.path().extension() == ".h5" && entry.path().filename().string()[0] != '.')
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Every snapshot the killed run left reads and passes the reader's checks; anything else in the
// snapshot folder is a temporary of an unfinished write (".NAME.tmp-XXXXXXXXXXXXXXXX").
void expectEveryFileCompleteOrTemporary(const fs::path& dir, const std::string& moment) {
  for (const fs::path& file : snapshotsIn(dir)) {
    SnapshotInfo info;
    EXPECT_NO_THROW(readSnapshot(file.string(), info)) << moment << ": " << file;
  }
  for (const auto& entry : fs::directory_iterator(dir / "snapshots")) {
    const std::string name = entry.path().filename().string();
    const bool finished = entry.path().extension() == ".h5" || entry.path().extension() == ".xdmf";
    const bool temporary = name[0] == '.' && name.find(".tmp-") != std::string::npos;
    EXPECT_TRUE(finished || temporary) << moment << ": unexpected file " << entry.path();
  }
}

TEST(ChainFaults, KilledAtRandomMomentsTheRestartsEndOnTheUninterruptedRunsParticles) {
  const fs::path dir = fs::path(EJECTA_BINARY_DIR) / "chain_faults";
  fs::remove_all(dir);
  std::string output;
  ASSERT_EQ(runCommand(kEjecta + " run " + kBaseScene + kScene + " --out " + (dir / "whole").string(), output), 0)
      << output;
  const std::vector<fs::path> wholeSnapshots = snapshotsIn(dir / "whole");
  ASSERT_EQ(wholeSnapshots.size(), 11u);

  // Kills between 0.4 s (start-up: the first snapshot is not yet written) and 2.5 s after each
  // start; four of them in a chain, the first of a fresh run, then of restarts.
  std::mt19937 random(24);
  std::uniform_real_distribution<double> delay(0.4, 2.5);
  const fs::path cut = dir / "cut";
  std::string command = kEjecta + " run " + kBaseScene + kScene + " --out " + cut.string();
  for (int kill = 0; kill < 4; ++kill) {
    const std::string seconds = std::to_string(delay(random));
    const int status = runCommand("timeout -s KILL " + seconds + " " + command, output);
    const std::string moment = "kill " + std::to_string(kill) + " after " + seconds + " s";
    // 137 (128 + SIGKILL) from timeout; 0 when the run finished first.
    ASSERT_TRUE(status == 137 || status == 0) << moment << " exit " << status << "\n" << output;
    expectEveryFileCompleteOrTemporary(cut, moment);
    if (snapshotsIn(cut).empty()) {
      // Killed before its first snapshot: nothing to resume, and the restart says so.
      EXPECT_NE(runCommand(kEjecta + " run --quiet --restart " + cut.string(), output), 0);
      EXPECT_NE(output.find(cut.string()), std::string::npos) << output;
      command = kEjecta + " run " + kBaseScene + kScene + " --overwrite --out " + cut.string();
    } else {
      command = kEjecta + " run --quiet --no-charts --threads 1 --restart " + cut.string();
    }
  }
  ASSERT_EQ(runCommand(command, output), 0) << output;
  expectEveryFileCompleteOrTemporary(cut, "after the last restart");
  for (const auto& entry : fs::directory_iterator(cut / "snapshots"))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
        << "a restart leaves no temporaries: " << entry.path();

  // The same snapshots, and the last one bit for bit.
  const std::vector<fs::path> cutSnapshots = snapshotsIn(cut);
  ASSERT_EQ(cutSnapshots.size(), wholeSnapshots.size());
  SnapshotInfo wholeInfo, cutInfo;
  const ParticleSet whole = readSnapshot(wholeSnapshots.back().string(), wholeInfo);
  const ParticleSet resumed = readSnapshot(cutSnapshots.back().string(), cutInfo);
  EXPECT_EQ(cutInfo.step, wholeInfo.step);
  EXPECT_EQ(cutInfo.time, wholeInfo.time);
  for (const FieldDifference& d : particleDifferences(whole, resumed))
    EXPECT_EQ(d.absolute, 0.0) << d.field << " differs after the kills";
  const auto summary = nlohmann::json::parse(readTextFile(cut / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
}

}  // namespace
}  // namespace ejecta::test
