#include "apps/launch_check.hpp"

#include <cstdlib>

#include "sim/parallel/communicator.hpp"

namespace ejecta::app {

namespace {

std::optional<int> integerVariable(const char* name) {
  const char* text = std::getenv(name);
  if (!text || !*text) return std::nullopt;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value < 0) return std::nullopt;
  return static_cast<int>(value);
}

}  // namespace

std::optional<int> launchedRanks() {
  if (const auto n = integerVariable("OMPI_COMM_WORLD_SIZE")) return n;
  return integerVariable("PMI_SIZE");
}

bool isFirstRank() {
  const auto rank = integerVariable("OMPI_COMM_WORLD_RANK") ? integerVariable("OMPI_COMM_WORLD_RANK")
                                                            : integerVariable("PMI_RANK");
  return !rank || *rank == 0;
}

std::optional<std::string> multiRankRefusal(const std::string& subcommand) {
  const std::optional<int> ranks = launchedRanks();
  if (!ranks || *ranks <= 1) return std::nullopt;
  if (!builtWithMpi())
    return "launched as " + std::to_string(*ranks) +
           " MPI ranks, but this ejecta runs on one rank: it was built without MPI (install "
           "libopenmpi-dev and rebuild; docs/parallel.md), and each rank would run the whole "
           "command and write the same output files. Run it without the MPI launcher, or with "
           "-np 1; each run is multi-threaded already (--threads).";
  if (distributedCommand(subcommand)) return std::nullopt;
  return "launched as " + std::to_string(*ranks) + " MPI ranks, but 'ejecta " + subcommand +
         "' runs on one rank (each rank would run the whole command and write the same output "
         "files); only 'ejecta run' and 'ejecta sweep' are distributed. Run it without the MPI "
         "launcher, or with -np 1.";
}

bool distributedCommand(const std::string& subcommand) {
  return builtWithMpi() && (subcommand == "run" || subcommand == "sweep");
}

}  // namespace ejecta::app
