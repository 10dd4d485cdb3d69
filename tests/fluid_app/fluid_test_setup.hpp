#pragma once
// Small lattice set-ups shared by the fluid tests (lattice units: dx = dt = 1 for the SI
// numbers given here, so velocities and pressures read directly as lattice values / scales).
#include <cmath>

#include "coupler_lib/scene/fluid_section.hpp"

namespace lbdem::testing_fluid {

// A box of nx x ny x nz cells, dx = 1 m, with nu chosen so that dt = 1 s at the given tau:
// then SI velocities equal lattice velocities and pressure p = 1000 kg/m^3 * p_lattice.
inline FluidParams lattice_params(int nx, int ny, int nz, double tau) {
  FluidParams p;
  p.cells = {nx, ny, nz};
  p.dx = 1.0;
  p.domain = {double(nx), double(ny), double(nz)};
  p.tau = tau;
  p.viscosity = (tau - 0.5) / 3.0;
  p.density = 1000.0;
  p.units = UnitConverter::from_tau(p.dx, p.tau, p.viscosity, p.density);
  return p;
}

// A smooth deterministic perturbation of the rest state, from global coordinates only.
inline double wave(int gx, int gy, int gz, int k) {
  return std::sin(0.7 * gx + 1.3 * gy + 0.4 * gz + 2.1 * k) * std::cos(0.3 * gx - 0.9 * gz + k);
}

}  // namespace lbdem::testing_fluid
