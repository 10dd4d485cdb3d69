#pragma once
// The macroscopic state of one rank's block of the lattice, in lattice units: the common input
// of the field writer, the time series, the stability watch and the validation. The solver
// fills it (density and the physical velocity, i.e. including half the forcing shift,
// docs/method.md Eq. (6)); everything downstream only reads it.
#include <array>
#include <cstddef>
#include <vector>

namespace lbdem {

// Which part of the global lattice a rank owns: nodes [lo, lo + n) of a global box of
// `global` nodes. Node (i, j, k) sits at the cell centre ((i, j, k) + 1/2) dx.
struct FieldBlock {
  std::array<int, 3> global{};
  std::array<int, 3> lo{};
  std::array<int, 3> n{};

  std::size_t cells() const { return std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]); }
  // x fastest, then y, then z (the order of the HDF5 datasets, z slowest).
  std::size_t index(int i, int j, int k) const {
    return std::size_t(i) + std::size_t(n[0]) * (std::size_t(j) + std::size_t(n[1]) * k);
  }
  long long global_cells() const {
    return static_cast<long long>(global[0]) * global[1] * global[2];
  }
};

struct MacroFields {
  FieldBlock box;
  std::vector<double> rho;  // one per node, lattice density (rest state 1)
  std::vector<double> u;    // three per node (ux, uy, uz interleaved), lattice velocity

  void resize(const FieldBlock& b) {
    box = b;
    rho.resize(b.cells());
    u.resize(3 * b.cells());
  }
};

}  // namespace lbdem
