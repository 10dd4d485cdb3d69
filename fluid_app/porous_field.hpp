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
//   sits at g + 1/2 (so the SI position divided by dx). On periodic axes the kernel takes the
//   minimum image of x - x_c with the global lattice length, so x_c may be any image.
// * `active` = false skips all porous work (the solver then runs its plain kernel). Set it
//   true once d/body are filled; FluidSolver::porous() allocates the arrays (d = 1, body = -1).
#include <array>
#include <cstdint>
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

template <class T>
struct PorousField {
  bool active = false;
  std::vector<float> d;               // porosity per local cell (with ghosts)
  std::vector<std::int32_t> body;     // body index per local cell (with ghosts), -1 none
  std::vector<PorousBody<T>> bodies;  // per-step body table
  // Written by the solver in every porous step: one entry per entry of `bodies`.
  std::vector<PenaltyExchange> exchange;
};

}  // namespace lbdem
