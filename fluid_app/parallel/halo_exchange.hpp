#pragma once
// Halo exchange of the AA-pattern lattice with the (up to 18) neighbour ranks that D3Q19
// links reach (6 faces, 12 edges; D3Q19 has no corner velocities).
//
// For a direction e, the "ghost list" holds the ghost locations (cell g beyond the e side,
// population j) whose source cell g - c_j is interior, and the "inner list" the interior
// locations (y, j) whose source y - c_j lies beyond the e side. The ghost list of one rank
// and the inner list of its neighbour describe the same lattice links in the same order.
//   after an even step (pull): neighbour's inner values  -> our ghost locations
//                              (post-collision values the next odd step streams in);
//   after an odd step  (push): our ghost values -> neighbour's inner locations
//                              (what our cells streamed across the boundary).
// Each link is copied once per step (5 values per face cell, 1 per edge cell), in a single
// round of messages, so the exchange can overlap with the update of the inner cells.
//
// Each list is, per population j, one box of local cells (the cells of a face or edge region
// whose source cell lies on the other side: the intersection of two boxes), visited in z, y, x
// order, so no index list is stored (docs/performance.md "Memory per cell").
#include <mpi.h>

#include <array>
#include <vector>

#include "fluid_app/lattice/d3q19.hpp"
#include "fluid_app/parallel/decomposition.hpp"

namespace lbdem {

// What this rank sent to other ranks (payload bytes, messages), summed over exchanges; the
// links are symmetric, so it also receives as much. Copies to itself are not counted.
struct HaloTraffic {
  long long bytes = 0;
  long long messages = 0;
  long long exchanges = 0;
};

template <class T>
class HaloExchange {
 public:
  HaloExchange(const Decomposition& dec, CellIndex stride);

  // Post the remote messages of this step (after every cell that feeds them is updated).
  void start(T* f, bool after_odd);
  // Copies to ourselves (periodic axes with one rank), waits, unpacks.
  void finish(T* f, bool after_odd);

  static int direction(int ex, int ey, int ez) { return (ex + 1) + 3 * (ey + 1) + 9 * (ez + 1); }
  const HaloTraffic& traffic() const { return traffic_; }

 private:
  // A list of links: population j's cells are the box cells[j], the list's entries run over
  // j, then the box in z, y, x order.
  struct LinkBoxes {
    std::array<CellRange, d3q19::Q> cells{};
    std::size_t size = 0;
  };
  struct Links {
    int neighbour = MPI_PROC_NULL;
    std::array<int, 3> e{};
    LinkBoxes ghost, inner;
    std::vector<T> send, recv;
  };
  MPI_Comm comm_;
  int rank_;
  LocalBox box_;
  CellIndex stride_;
  std::array<Links, 27> links_;
  std::vector<MPI_Request> requests_;
  HaloTraffic traffic_;
};

extern template class HaloExchange<double>;
extern template class HaloExchange<float>;

}  // namespace lbdem
