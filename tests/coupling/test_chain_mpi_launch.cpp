// `mpirun -np N ejecta ...` of a command that runs on one rank (apps/launch_check.hpp): every
// command of a build without MPI, every command but `run` of a build with it. Each rank would
// run the whole command and write the same files, so the command refuses before doing
// anything, says why once (rank 0), and leaves the output folder as it was. The launchers'
// environments are set by hand here (Open MPI's OMPI_COMM_WORLD_SIZE/RANK, PMI's PMI_SIZE/RANK),
// so the test needs no MPI installation; the distributed `run` itself is tested under mpirun
// (tests/parallel, and the ejecta_run_np2 command test in tests/CMakeLists.txt).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "sim/parallel/communicator.hpp"
#include "support/command_line.hpp"

namespace fs = std::filesystem;

namespace {

using ejecta::test::kEjecta;
using ejecta::test::runCommand;

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_mpi_launch_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(MpiLaunch, TwoOpenMpiRanksOfAOneRankCommandAreRefusedBeforeAnythingIsWritten) {
  const fs::path dir = freshDir("ompi");
  std::string out;
  // Without MPI even `run` is refused; with it, `run` is distributed and `verify` is not.
  const std::string command = ejecta::builtWithMpi() ? " verify sod_1d --out " : " run --out ";
  const int rc = runCommand("OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 " + kEjecta + command +
                                (dir / "run").string(),
                            out);
  EXPECT_EQ(rc, 2) << out;
  const std::string why = ejecta::builtWithMpi()
                              ? "launched as 2 MPI ranks, but 'ejecta verify' runs on one rank"
                              : "launched as 2 MPI ranks, but this ejecta runs on one rank";
  EXPECT_NE(out.find(why), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "run"));  // nothing started
  fs::remove_all(dir);
}

TEST(MpiLaunch, OnlyRankZeroSaysWhy) {
  std::string out;
  EXPECT_EQ(runCommand("PMI_SIZE=4 PMI_RANK=3 " + kEjecta + " keys", out), 2) << out;
  EXPECT_EQ(out, "");  // rank 3 is silent: the message appears once, from rank 0
}

TEST(MpiLaunch, OneRankRunsAsUsual) {
  std::string out;
  EXPECT_EQ(runCommand("OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0 " + kEjecta + " keys", out), 0)
      << out;
  EXPECT_NE(out.find("sph.kernel"), std::string::npos) << out.substr(0, 500);
}

}  // namespace
