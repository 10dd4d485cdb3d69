#pragma once
// The porosity field of homogenized LBM (HLBM) as the kernel reads it.
//
// The HLBM part fills these arrays; the fluid kernel turns them into a velocity shift through
// the same exact-difference (Kupershtokh) step that carries the uniform body force
// (docs/method.md Eqs. (4)-(5)):
//   u+ = v + dt F / rho + (1 - d) (u_p - v),   u_p = v_b + omega_b x minimum_image(x - x_c).
//
// Contract for the filler (all values in LATTICE units, see UnitConverter):
// * `d` and `body` have one entry per local cell INCLUDING the ghost layer, indexed like the
//   lattice (LocalBox::index). The kernel reads only the rank's interior cells, so only those
//   must be filled; ghosts may be filled for the filler's own use (momentum exchange).
// * d = 1 fluid, 0 solid, in between on the smoothed surface. Cells with d == 1 are unaffected.
// * body = index into `bodies`, or -1 for a static porous cell (u_p = 0).
// * bodies[k].centre is the body's centre in global lattice coordinates, where global node g
//   sits at g + 1/2 (so the SI position divided by dx), wrapped into [0, L) on periodic axes
//   (L the global lattice length): the kernel's minimum image of x - x_c subtracts at most one
//   L.
// * `active` = false skips all porous work (the solver then runs its plain kernel). Set it
//   true once d/body are filled; FluidSolver::porous() allocates the arrays (d = 1, body = -1).
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace lbdem {

template <class T>
struct PorousBody {
  std::array<T, 3> centre{};    // x_c, lattice units (global frame)
  std::array<T, 3> velocity{};  // v, lattice units
  std::array<T, 3> omega{};     // angular velocity, rad per time step
};

// u_p = v + w x r (docs/method.md Eq. (7)) at lever arm r from the centre, lattice units, in the
// arithmetic of R (the lattice's T, or double for the link-wise loads). The kernel writes the same
// expression on its gathered body table (fluid_app/kernel/aa_kernel.hpp).
template <class R, class T>
std::array<R, 3> solid_velocity(const PorousBody<T>& b, const std::array<R, 3>& r) {
  return {R(b.velocity[0]) + R(b.omega[1]) * r[2] - R(b.omega[2]) * r[1],
          R(b.velocity[1]) + R(b.omega[2]) * r[0] - R(b.omega[0]) * r[2],
          R(b.velocity[2]) + R(b.omega[0]) * r[1] - R(b.omega[1]) * r[0]};
}

// What the penalization exchanged with the lattice in one step, summed over the interior
// cells of this rank that a body owns (body index k), lattice units, about the body's centre
// (docs/method-loads.md). With pen = rho (1 - d)(u_p - v) and u+ the shifted velocity:
struct PenaltyExchange {
  std::array<double, 3> impulse{};         // P = sum pen: momentum given to the lattice
  std::array<double, 3> moment{};          // sum r x pen
  std::array<double, 3> covered{};         // Q = sum (1 - d) rho u+: fluid the body covers
  std::array<double, 3> covered_moment{};  // sum (1 - d) r x rho u+
};

// The per-step body table in the kernel's layout, written once by the filler and read by the
// kernel as it is: nine flat arrays (centre, velocity, angular velocity components; gathers
// from flat arrays vectorize), each with an entry 0 of zeros for body -1 and body k at k + 1.
template <class T>
class BodyTable {
 public:
  BodyTable() = default;
  BodyTable(std::initializer_list<PorousBody<T>> bodies) {
    for (const auto& b : bodies) push_back(b);
  }

  std::size_t size() const { return column_[0].size() - 1; }
  PorousBody<T> operator[](std::size_t k) const {
    PorousBody<T> b;
    for (int a = 0; a < 3; ++a) {
      b.centre[a] = column_[a][k + 1];
      b.velocity[a] = column_[3 + a][k + 1];
      b.omega[a] = column_[6 + a][k + 1];
    }
    return b;
  }
  void set(std::size_t k, const PorousBody<T>& b) {
    for (int a = 0; a < 3; ++a) {
      column_[a][k + 1] = b.centre[a];
      column_[3 + a][k + 1] = b.velocity[a];
      column_[6 + a][k + 1] = b.omega[a];
    }
  }
  void push_back(const PorousBody<T>& b) {
    for (auto& c : column_) c.push_back(T(0));
    set(size() - 1, b);
  }
  void clear() {
    for (auto& c : column_) c.assign(1, T(0));
  }
  // Column m (0-2 centre, 3-5 velocity, 6-8 angular velocity), entry 0 for body -1.
  const T* column(int m) const { return column_[static_cast<std::size_t>(m)].data(); }

 private:
  std::array<std::vector<T>, 9> column_ = [] {
    std::array<std::vector<T>, 9> c;
    for (auto& v : c) v.assign(1, T(0));
    return c;
  }();
};

template <class T>
struct PorousField {
  bool active = false;
  std::vector<float> d;            // porosity per local cell (with ghosts)
  std::vector<std::int32_t> body;  // body index per local cell (with ghosts), -1 none
  BodyTable<T> bodies;             // per-step body table
  // Written by the solver in every porous step: one entry per entry of `bodies`.
  std::vector<PenaltyExchange> exchange;
};

}  // namespace lbdem
