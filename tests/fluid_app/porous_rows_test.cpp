#include <gtest/gtest.h>
#include <mpi.h>

#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"

namespace lbdem {
namespace {

// The cost model's counter of porous-row cells: every row along x with a covered cell (d < 1)
// counts whole, a row of fluid cells (d = 1) not at all.
TEST(PorousRows, CountsWholeRowsWithACoveredCell) {
  FluidSolver<double> s(testing_fluid::lattice_params(10, 6, 4, 0.8), MPI_COMM_SELF);
  EXPECT_EQ(s.porous_row_cells(), 0.0);  // no porous field yet
  PorousField<double>& field = s.porous();
  field.active = true;
  EXPECT_EQ(s.porous_row_cells(), 0.0);  // all fluid
  const LocalBox& b = s.box();
  auto set = [&](int x, int y, int z, float d) { field.d[std::size_t(b.index(x, y, z))] = d; };
  set(3, 2, 1, 0.0f);  // two covered cells of one row: one row
  set(7, 2, 1, 0.5f);
  set(1, 6, 4, 0.0f);  // the first and the last cell of two other rows
  set(10, 1, 2, 0.99f);
  set(5, 3, 3, 1.0f);  // written, but fluid
  EXPECT_EQ(s.porous_row_cells(), 3.0 * 10);
  set(5, 3, 3, 0.0f);
  EXPECT_EQ(s.porous_row_cells(), 4.0 * 10);
  field.active = false;
  EXPECT_EQ(s.porous_row_cells(), 0.0);  // the kernel then runs no porous path
}

// A ghost cell (x = 0) is no part of the row the kernel updates.
TEST(PorousRows, IgnoresGhostCells) {
  FluidSolver<double> s(testing_fluid::lattice_params(8, 3, 3, 0.8), MPI_COMM_SELF);
  PorousField<double>& field = s.porous();
  field.active = true;
  const LocalBox& b = s.box();
  field.d[std::size_t(b.index(0, 2, 2))] = 0.0f;
  field.d[std::size_t(b.index(9, 1, 1))] = 0.0f;
  EXPECT_EQ(s.porous_row_cells(), 0.0);
  field.d[std::size_t(b.index(8, 1, 1))] = 0.0f;
  EXPECT_EQ(s.porous_row_cells(), 8.0);
}

}  // namespace
}  // namespace lbdem
