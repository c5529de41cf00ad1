// Run control from the command line (apps/cmd_run.cpp): a batch job's log gets plain progress
// lines (no carriage returns) every --progress-every seconds, --quiet none; a finished run is
// extended with --restart DIR --set time.t_end=...; a key that cannot change at a restart is
// refused with exit status 1 and the reason; summary.json gives the time loop's and the whole
// command's wall time.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "support/command_line.hpp"
#include "support/temp_dir_test.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::readTextFile;
using ejecta::test::runCommand;

class RunControl : public ejecta::test::TempDirTest {
 protected:
  std::string sod() const { return std::string(EJECTA_SOURCE_DIR) + "/scenes/verification/sod_1d.toml"; }
};

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST_F(RunControl, ALogGetsPlainProgressLines) {
  std::string lines;  // stdout and stderr: stderr is a pipe here, not a terminal
  ASSERT_EQ(runCommand(kEjecta + " run " + sod() + " --out " + (dir_ / "a").string() +
                           " --no-charts --threads 1 --progress-every 0.001",
                       lines),
            0)
      << lines;
  EXPECT_GE(countOf(lines, "\n[ejecta] step "), 2u) << lines;  // after the "running" line
  EXPECT_EQ(lines.find('\r'), std::string::npos);               // no live-line rewrites
  EXPECT_NE(lines.find(" wall\n"), std::string::npos) << lines;
  std::string out;
  ASSERT_EQ(runCommand(kEjecta + " run " + sod() + " --out " + (dir_ / "b").string() +
                           " --no-charts --threads 1 --quiet --progress-every 0.001",
                       out),
            0)
      << out;
  EXPECT_EQ(countOf(out, "[ejecta] step"), 0u);
}

TEST_F(RunControl, AFinishedRunIsExtendedAtARestart) {
  std::string out;
  const std::string run = (dir_ / "run").string();
  ASSERT_EQ(runCommand(kEjecta + " run " + sod() + " --set 'time.t_end=0.1 s' --out " + run +
                           " --no-charts --quiet --threads 1",
                       out),
            0)
      << out;
  ASSERT_EQ(runCommand(kEjecta + " run --restart " + run + " --set 'time.t_end=0.15 s' --quiet --threads 1", out), 0)
      << out;
  const nlohmann::json summary = nlohmann::json::parse(readTextFile(dir_ / "run" / "summary.json"));
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_DOUBLE_EQ(summary["t_end"].get<double>(), 0.15);
  EXPECT_GE(summary["total_wall_seconds"].get<double>(), 0.0);
  EXPECT_NE(out.find("s with set-up and outputs"), std::string::npos) << out;
  // Only the listed keys; the reason and the way out in the message.
  EXPECT_EQ(runCommand(kEjecta + " run --restart " + run + " --set sph.eta=1.3 --quiet", out), 1) << out;
  EXPECT_NE(out.find("key 'sph.eta' cannot change at a restart"), std::string::npos) << out;
  EXPECT_NE(out.find("start a new run"), std::string::npos) << out;
  EXPECT_EQ(runCommand(kEjecta + " run " + sod() + " --restart " + run + " --quiet", out), 1) << out;
}

}  // namespace

namespace {

TEST(CommandLine, EveryComputingCommandTakesThreads) {
  // apps/thread_limit.hpp: the commands that do not hand a count to a library cap OpenMP and TBB.
  for (const char* command : {"run", "verify", "fields", "crater", "sweep", "viewfactor", "thermal",
                              "render", "whipple", "undex-reference"}) {
    std::string out;
    ASSERT_EQ(runCommand(kEjecta + " " + command + " --help", out), 0) << command;
    EXPECT_NE(out.find("--threads"), std::string::npos) << command << " has no --threads:\n" << out;
  }
  std::string out;
  EXPECT_EQ(runCommand(kEjecta + " fields nothing.h5 --threads 0", out), 1) << out;
  EXPECT_NE(out.find("--threads must be a whole number from 1"), std::string::npos) << out;
}

}  // namespace
