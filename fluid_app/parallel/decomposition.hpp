#pragma once
// Cartesian block decomposition of the global lattice over the ranks of one communicator.
//
// MPI_Dims_create factors the rank count; the factors go to the axes from the longest to the
// shortest (ties: z before y before x), with x counted at half its length, so that x (the
// contiguous axis of the lattice) is split last: halos stay long contiguous rows and the kernel
// keeps long vector loops. A cube on 2 ranks is cut along z, on 12 ranks into 2 x 2 x 3. Uneven
// sizes are fine: the first N % p blocks of an axis get one cell more. Every rank knows the rank of
// each of its 26 neighbours (MPI_PROC_NULL across a non-periodic face), periodic images included (a
// rank can be its own neighbour).
//
// With axis weights (balanced_weights in balance.hpp) the grid of blocks stays rectilinear, so
// every face is shared by exactly two blocks as before, but the cuts of each axis are placed so
// that every slab of blocks along that axis holds the same weight: a settled bed or a dense
// cloud of bodies is split finer where its work is.
#include <mpi.h>

#include <array>
#include <vector>

#include "fluid_app/lattice/local_box.hpp"

namespace lbdem {

// Owns a Cartesian communicator (freed on destruction; move-only).
class Decomposition {
 public:
  // Collective over `comm`. `dims` entries that are 0 are chosen by MPI_Dims_create.
  // `weights`: per axis, the work of each slice of cells (empty: equal blocks).
  Decomposition(MPI_Comm comm, std::array<int, 3> global, std::array<bool, 3> periodic,
                std::array<int, 3> dims = {0, 0, 0},
                const std::array<std::vector<double>, 3>& weights = {});
  ~Decomposition();
  Decomposition(const Decomposition&) = delete;
  Decomposition& operator=(const Decomposition&) = delete;
  Decomposition(Decomposition&& o) noexcept;
  Decomposition& operator=(Decomposition&&) = delete;

  MPI_Comm comm() const { return cart_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  const std::array<int, 3>& dims() const { return dims_; }
  const std::array<int, 3>& coords() const { return coords_; }
  bool periodic(int axis) const { return periodic_[axis]; }
  const LocalBox& box() const { return box_; }
  // Rank of the neighbour at offset (ex, ey, ez) in {-1,0,1}^3, MPI_PROC_NULL if none.
  int neighbour(int ex, int ey, int ez) const {
    return neighbour_[(ex + 1) + 3 * (ey + 1) + 9 * (ez + 1)];
  }

 private:
  MPI_Comm cart_ = MPI_COMM_NULL;
  int rank_ = 0, size_ = 1;
  std::array<int, 3> dims_{}, coords_{};
  std::array<bool, 3> periodic_{};
  LocalBox box_;
  std::array<int, 27> neighbour_{};
};

// Cells and first global index of block `r` of `p` along an axis of `n` cells.
struct Extent {
  int count = 0;
  int offset = 0;
};
Extent block_extent(int n, int p, int r);

// Block `r` of `p` along an axis whose slices weigh `w` (one entry per cell): the cuts split
// the cumulative weight into p equal parts, each block at least one cell.
Extent weighted_extent(const std::vector<double>& w, int p, int r);

}  // namespace lbdem
