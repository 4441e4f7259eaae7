// main() of the MPI tests: MPI up before GoogleTest runs, down after; only the root prints.
#include <gtest/gtest.h>

#include "parallel/communicator.hpp"

int main(int argc, char** argv) {
  rfmems::MpiSession session(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (!rfmems::Communicator::world().is_root()) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  int failed = RUN_ALL_TESTS();
  // Every rank must agree on the verdict, or mpirun reports the root's only.
  const auto world = rfmems::Communicator::world();
  return world.max(static_cast<rfmems::Index>(failed)) != 0 ? 1 : 0;
}
