#pragma once
// The part of the global lattice one rank owns, with one ghost layer on every side.
//
// Local coordinates run 0..n+1 per axis; 1..n are the rank's own ("interior") cells, 0 and
// n+1 the ghost layer. A cell's linear index is x + sx*(y + sy*z) with sx = nx+2, sy = ny+2
// (x fastest). Interior cell (x, y, z) is global cell offset + (x-1, y-1, z-1).
#include <array>
#include <cstddef>
#include <cstdint>

namespace lbdem {

using CellIndex = std::int64_t;

struct LocalBox {
  std::array<int, 3> n{};       // interior cells per axis
  std::array<int, 3> offset{};  // global index of the first interior cell
  std::array<int, 3> global{};  // global lattice size

  int sx() const { return n[0] + 2; }
  int sy() const { return n[1] + 2; }
  int sz() const { return n[2] + 2; }
  CellIndex cells_with_ghosts() const { return CellIndex(sx()) * sy() * sz(); }
  CellIndex interior_cells() const { return CellIndex(n[0]) * n[1] * n[2]; }
  CellIndex index(int x, int y, int z) const {
    return x + CellIndex(sx()) * (y + CellIndex(sy()) * z);
  }
  // Linear offset of the neighbour in direction (cx, cy, cz).
  CellIndex shift(int cx, int cy, int cz) const {
    return cx + CellIndex(sx()) * (cy + CellIndex(sy()) * cz);
  }
  bool interior(int x, int y, int z) const {
    return x >= 1 && x <= n[0] && y >= 1 && y <= n[1] && z >= 1 && z <= n[2];
  }
  std::array<int, 3> coords(CellIndex idx) const {
    const int x = int(idx % sx());
    const int y = int((idx / sx()) % sy());
    const int z = int(idx / (CellIndex(sx()) * sy()));
    return {x, y, z};
  }
};

// A half-open range of local cells [lo, hi) per axis.
struct CellRange {
  std::array<int, 3> lo{};
  std::array<int, 3> hi{};
  bool empty() const { return lo[0] >= hi[0] || lo[1] >= hi[1] || lo[2] >= hi[2]; }
};

}  // namespace lbdem
