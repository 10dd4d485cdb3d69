// GoogleTest main with MPI initialised: the fluid solver is built on a communicator even on
// one rank. Linked before gtest_main, so this main wins.
#include <gtest/gtest.h>
#include <mpi.h>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  testing::InitGoogleTest(&argc, argv);
  const int rc = RUN_ALL_TESTS();
  MPI_Finalize();
  return rc;
}
