// Ctrl-C during `ejecta run` (docs/robustness.md): the run stops after its step with a last
// snapshot and summary.json of status "interrupted", exits 130, and `--restart` finishes it with
// the same answer as a run never interrupted (bit-for-bit restart: the same final energy).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "support/command_line.hpp"

namespace fs = std::filesystem;

namespace ejecta::test {
namespace {

// The corpus's base scene at 0.01 m (2,558 particles, ~4 s on one thread): long enough to be
// interrupted part-way, after its second of four snapshot intervals.
const std::string kArgs = " run " + std::string(EJECTA_SOURCE_DIR) +
                          "/tests/hostile/base_scene.toml --quiet --no-charts --threads 1"
                          " --set 'bodies[0].spacing=0.01 m' --set 'bodies[1].spacing=0.01 m'"
                          " --set 'time.t_end=0.2 ms' --set 'output.snapshot_interval=0.05 ms'";

TEST(ChainInterrupt, SigintStopsWithASnapshotAndTheRestartFinishesTheSameRun) {
  const fs::path dir = fs::path(EJECTA_BINARY_DIR) / "chain_interrupt";
  fs::remove_all(dir);
  std::string output;
  ASSERT_EQ(runCommand(kEjecta + kArgs + " --out " + (dir / "whole").string(), output), 0) << output;

  // SIGINT once the run is stepping: when its second snapshot (t = 0.05 ms of 0.2) exists, the
  // handler is installed and the steps are under way. A fixed delay (1.5 s, as this test had)
  // can land before the handler on a loaded machine: the process then dies of the signal with
  // no summary (seen twice beside other runs). The shell's status is the run's own (130).
  const fs::path cutDir = dir / "cut";
  const std::string marker = (cutDir / "snapshots" / "snap_0001.h5").string();
  ASSERT_EQ(runCommand(kEjecta + kArgs + " --out " + cutDir.string() +
                           " 2>&1 & pid=$!; i=0; while [ ! -e " + marker +
                           " ] && kill -0 $pid 2>/dev/null && [ $i -lt 2400 ]; do sleep 0.025; "
                           "i=$((i+1)); done; kill -INT $pid; wait $pid",
                       output),
            130)
      << output;
  EXPECT_NE(output.find("interrupted"), std::string::npos) << output;
  const auto cut = nlohmann::json::parse(readTextFile(dir / "cut" / "summary.json"));
  EXPECT_EQ(cut["status"], "interrupted");
  EXPECT_LT(cut["t_end"].get<double>(), 2e-4);
  EXPECT_NE(cut["message"].get<std::string>().find("--restart"), std::string::npos);

  ASSERT_EQ(runCommand(kEjecta + " run --quiet --no-charts --threads 1 --restart " + (dir / "cut").string(), output), 0)
      << output;
  const auto resumed = nlohmann::json::parse(readTextFile(dir / "cut" / "summary.json"));
  const auto whole = nlohmann::json::parse(readTextFile(dir / "whole" / "summary.json"));
  EXPECT_EQ(resumed["status"], "completed");
  EXPECT_EQ(resumed["steps"], whole["steps"]);
  EXPECT_EQ(resumed["energy"]["final"].get<double>(), whole["energy"]["final"].get<double>());
}

}  // namespace
}  // namespace ejecta::test
