#pragma once
// Refuses a launch by an MPI launcher (mpirun, mpiexec, srun with PMI) with more than one rank
// of a command that runs on one: N copies of it would race for the same output files. `ejecta
// run` and `ejecta sweep` are distributed in a build with MPI (sim/parallel/); every other
// command, and every command of a build without MPI, runs on one rank.
#include <optional>
#include <string>

namespace ejecta::app {

// The number of ranks the launcher started, from its environment (Open MPI's
// OMPI_COMM_WORLD_SIZE, MPICH and Slurm PMI's PMI_SIZE); nothing when not under a launcher.
std::optional<int> launchedRanks();

// The refusal for a launch of `ranks` > 1 ranks, or nothing when the launch is fine. Only rank 0
// should print it (isFirstRank), so the message appears once.
std::optional<std::string> multiRankRefusal(const std::string& subcommand);
// `run` and `sweep` (in a build with MPI).
bool distributedCommand(const std::string& subcommand);
bool isFirstRank();

}  // namespace ejecta::app
