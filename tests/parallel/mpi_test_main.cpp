// The main() of the distributed tests (run by CTest under mpirun, tests/CMakeLists.txt): MPI for
// the whole process, GoogleTest's report from rank 0 only, and a failure on any rank fails all.
#include <gtest/gtest.h>

#include "sim/parallel/communicator.hpp"

int main(int argc, char** argv) {
  ejecta::MpiSession mpi(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  const auto world = ejecta::worldCommunicator();
  if (!world->isRoot()) {
    ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
  return world->sum(static_cast<std::uint64_t>(failed)) > 0 ? 1 : 0;
}
