#pragma once
// SI <-> lattice unit conversion (one place, like OpenLB's UnitConverter).
//
// Lattice units: dx = dt = rho = 1. With BGK, nu_lattice = c_s^2 (tau - 1/2), c_s^2 = 1/3
// (docs/method.md Eq. (3)), so the physical time step follows from the resolution and tau:
//   dt = (tau - 1/2) dx^2 / (3 nu).
// Lattice node g (0-based global index along an axis) sits at x = (g + 1/2) dx, so the
// domain [0, L] is covered by N = L / dx cells and half-way walls lie exactly on 0 and L.
#include <string>

namespace lbdem {

// Steps of length dt between two events `interval` seconds apart: the nearest whole number, at
// least one (output, control and snapshot intervals of both programs).
long steps_between(double interval, double dt);

// Limits of the method, checked by UnitConverter::check.
struct UnitLimits {
  double min_tau = 0.505;  // closer to 1/2 the BGK model loses stability (nu_lattice -> 0)
  double max_mach = 0.3;   // compressibility error of the 2nd-order equilibrium grows as Ma^2
};

struct UnitConverter {
  double dx = 1;   // m per cell
  double dt = 1;   // s per step
  double rho = 1;  // kg/m^3 of the fluid (lattice density 1)
  double nu = 1;   // m^2/s kinematic viscosity
  double tau = 1;  // BGK relaxation time (lattice)
  // Optional expected flow scales (0 = unknown), used only for the logged Ma and Re.
  double char_velocity = 0;  // m/s
  double char_length = 0;    // m

  static UnitConverter from_tau(double dx, double tau, double nu, double rho);

  double nu_lattice() const { return (tau - 0.5) / 3.0; }
  double velocity() const { return dx / dt; }                           // m/s per lattice unit
  double acceleration() const { return dx / (dt * dt); }                // m/s^2 per lattice unit
  double force() const { return rho * dx * dx * dx * dx / (dt * dt); }  // N per lattice unit
  double force_density() const { return rho * dx / (dt * dt); }         // N/m^3 per lattice unit
  double torque() const { return force() * dx; }                        // N m per lattice unit
  double pressure() const { return rho * dx * dx / (dt * dt); }         // Pa per lattice unit
  double mach(double u_si) const { return u_si / velocity() * 1.7320508075688772; }  // u / c_s
  double reynolds(double u_si, double length_si) const { return u_si * length_si / nu; }

  // Expected lattice Mach and Reynolds numbers from char_velocity / char_length (0 if unset).
  double expected_mach() const { return mach(char_velocity); }
  double expected_reynolds() const { return reynolds(char_velocity, char_length); }

  // The derived numbers as a few log lines (dx, dt, nu_lattice, tau, Ma, Re, scales).
  std::string describe() const;
  // Empty when the parameters are inside the method's range; otherwise a message that says
  // what is wrong and what to change (tau too close to 1/2, expected Mach too high).
  std::string check(const UnitLimits& limits = {}) const;
};

}  // namespace lbdem
