#include <gtest/gtest.h>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_Core.hpp>

#include "drivers/mpi_startup.hpp"

// Initialises MPI and Kokkos; only rank 0 prints gtest's report.
int main(int argc, char** argv) {
  grout::prefer_local_mpi_startup();
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (Tpetra::getDefaultComm()->getRank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
