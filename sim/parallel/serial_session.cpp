// The build without MPI: one serial rank (sim/parallel/communicator.hpp). CMake compiles this
// file instead of mpi_communicator.cpp when it finds no MPI.
#include "sim/parallel/communicator.hpp"

namespace ejecta {

bool builtWithMpi() { return false; }

std::shared_ptr<const Communicator> worldCommunicator() {
  return std::make_shared<SerialCommunicator>();
}

MpiSession::MpiSession(int*, char***) {}
MpiSession::~MpiSession() = default;
void MpiSession::abortAll(int) {}

}  // namespace ejecta
