#pragma once
// Rebalancing at a restart (fluid.decomposition: balanced, docs/scaling.md).
//
// Every fluid checkpoint records the work of the lattice as it was then: per global slice of
// cells along each axis, cells + (covered_cell_weight - 1) x the cells a body covered
// (measure_work, from the porosity field: the band and the interiors), the load imbalance of
// that work over the fluid ranks (max / mean), and the slice weights the checkpoint's own cuts
// were placed by. A restart with decomposition: balanced keeps those cuts (the same layout, so
// the restart continues the run bit for bit) unless the measured imbalance exceeds
// fluid.rebalance_above or the fluid rank count changed; then it cuts anew by the measured work
// (weighted_extent), and the run continues to round-off (the loads' partial sums are grouped
// by the new blocks). The halo exchange and the body routing follow any rectilinear layout.
#include <mpi.h>

#include <array>
#include <span>
#include <string>
#include <vector>

#include "coupler_lib/scene/fluid_section.hpp"
#include "fluid_app/lattice/local_box.hpp"

namespace lbdem {

using SliceWeights = std::array<std::vector<double>, 3>;  // per axis, one entry per cell

// What a checkpoint records about the work and the layout.
struct CheckpointWork {
  SliceWeights measured;  // measured slice work (empty: a checkpoint without it)
  double imbalance = 1;   // max / mean over the ranks of the measured weighted work
  SliceWeights layout;    // the weights the checkpoint's cuts came from (empty: regular blocks)
  int fluid_ranks = 0;    // the fluid rank count that wrote it
};

// Collective over `comm`: the measured slice work of the whole lattice and its imbalance over
// the ranks. `d`: the porosity of this rank's block with ghosts (empty: no bodies).
CheckpointWork measure_work(const LocalBox& box, std::span<const float> d,
                            double covered_cell_weight, MPI_Comm comm);

// Collective: the load imbalance (max / mean over the blocks of the weighted work) that blocks
// cut by `weights` on a grid of `dims` would hold (as Decomposition cuts them), counted on the
// porosity `d` of this rank's block as it is now: what a cut would give, before anything moves.
// In-run rebalancing cuts only when it is lower than the imbalance now (a rectilinear grid
// equalizes slabs, and can leave one small dense spot worse off).
double imbalance_of_cuts(const LocalBox& box, std::span<const float> d, double covered_cell_weight,
                         const SliceWeights& weights, const std::array<int, 3>& dims,
                         MPI_Comm comm);

// The layout of a restart: the weights to cut by (empty: regular blocks), why (for the log),
// and whether its blocks are the checkpoint's (each rank then takes back its own covered
// momentum; otherwise it goes to the lowest rank that holds the body).
struct LayoutChoice {
  SliceWeights weights;
  std::string why;
  bool same_as_checkpoint = false;
};

// Pure; the same on every rank.
LayoutChoice restart_layout(const FluidParams& fluid, const CheckpointWork& at, int fluid_ranks);

}  // namespace lbdem
