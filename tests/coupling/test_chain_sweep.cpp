// `ejecta sweep` through the command line (apps/cmd_sweep.cpp): a variant whose run stops is
// reported as failed in the printed table and in sweep.csv, and the sweep exits with status 2, so
// a partial result is never read as a finished one.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "support/command_line.hpp"
#include "support/periodic_blast.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::readTextFile;
using ejecta::test::runCommand;
using ejecta::test::writeTextFile;

TEST(SweepCommand, AStoppedVariantIsMarkedFailed) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_chain_sweep_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  writeTextFile(dir / "blast.toml", ejecta::test::periodicBlastScene());
  // Variant 1 asks for a smallest step far above the blast's first one: it stops at once.
  std::string output;
  const int rc = runCommand(kEjecta + " sweep " + (dir / "blast.toml").string() +
                                " --vary 'time.dt_min=0,0.01' --set 'time.t_end=0.005' --jobs 1 --out " +
                                (dir / "out").string(),
                            output);
  EXPECT_EQ(rc, 2) << output;
  EXPECT_NE(output.find("status"), std::string::npos) << output;
  EXPECT_NE(output.find("completed"), std::string::npos) << output;
  EXPECT_NE(output.find("FAILED"), std::string::npos) << output;
  const std::string csv = readTextFile(dir / "out" / "sweep.csv");
  EXPECT_NE(csv.find("\n0,0,completed,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n1,0.01,failed,"), std::string::npos) << csv;
  fs::remove_all(dir);
}

}  // namespace
