#pragma once
// Moving a lattice from one rectilinear layout to another while the program runs (in-run
// rebalancing, docs/scaling.md): each new block takes its cells from the old blocks it
// overlaps, in one MPI_Alltoallv. The values keep their bits, so the moved lattice is the one a
// checkpoint of the old layout read back on the new one would give.
#include <mpi.h>

#include <vector>

#include "fluid_app/lattice/local_box.hpp"

namespace lbdem {

// Collective over `comm` (same ranks, same order as the layouts'). `values`: this rank's
// interior cells of the `from` block, `components` arrays one after the other, cells x fastest
// (FluidSolver::interior_populations). Returns the same for the `to` block.
template <class T>
std::vector<T> move_blocks(const std::vector<T>& values, int components, const LocalBox& from,
                           const LocalBox& to, MPI_Comm comm);

extern template std::vector<double> move_blocks(const std::vector<double>&, int, const LocalBox&,
                                                const LocalBox&, MPI_Comm);
extern template std::vector<float> move_blocks(const std::vector<float>&, int, const LocalBox&,
                                               const LocalBox&, MPI_Comm);

}  // namespace lbdem
