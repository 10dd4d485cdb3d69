// GoogleTest main with MPI initialised: the fluid solver is built on a communicator even on
// one rank. Linked before gtest_main, so this main wins.
#include <gtest/gtest.h>
#include <mpi.h>

// Under AddressSanitizer: Open MPI keeps allocations from MPI_Init (partly in components it
// has unloaded by exit) that LeakSanitizer reports as leaks and turns into a failing exit
// code, which breaks GoogleTest's test discovery at build time. CI runs with
// detect_leaks=0 for the same reason; the other ASan/UBSan checks stay on.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  testing::InitGoogleTest(&argc, argv);
  const int rc = RUN_ALL_TESTS();
  MPI_Finalize();
  return rc;
}
