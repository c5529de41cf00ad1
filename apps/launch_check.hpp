#pragma once
// Refuses a launch by an MPI launcher (mpirun, mpiexec, srun with PMI) with more than one rank:
// this build runs one rank, and N copies of one command would race for the same output files
// (distributed runs over MPI are not built yet).
#include <optional>
#include <string>

namespace ejecta::app {

// The number of ranks the launcher started, from its environment (Open MPI's
// OMPI_COMM_WORLD_SIZE, MPICH and Slurm PMI's PMI_SIZE); nothing when not under a launcher.
std::optional<int> launchedRanks();

// The refusal for a launch of `ranks` > 1 ranks, or nothing when the launch is fine. Only rank 0
// should print it (isFirstRank), so the message appears once.
std::optional<std::string> multiRankRefusal();
bool isFirstRank();

}  // namespace ejecta::app
