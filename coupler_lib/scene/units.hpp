#pragma once
// SI <-> lattice unit conversion (one place, like OpenLB's UnitConverter).
//
// Lattice units: dx = dt = rho = 1. With BGK, nu_lattice = c_s^2 (tau - 1/2), c_s^2 = 1/3
// (paper, Eq. viscosity), so the physical time step follows from the resolution and tau:
//   dt = (tau - 1/2) dx^2 / (3 nu).
namespace lbdem {

struct UnitConverter {
  double dx = 1;   // m per cell
  double dt = 1;   // s per step
  double rho = 1;  // kg/m^3 of the fluid (lattice density 1)
  double nu = 1;   // m^2/s kinematic viscosity
  double tau = 1;  // BGK relaxation time (lattice)

  static UnitConverter from_tau(double dx, double tau, double nu, double rho);

  double nu_lattice() const { return (tau - 0.5) / 3.0; }
  double velocity() const { return dx / dt; }                           // m/s per lattice unit
  double acceleration() const { return dx / (dt * dt); }                // m/s^2 per lattice unit
  double force() const { return rho * dx * dx * dx * dx / (dt * dt); }  // N per lattice unit
  double torque() const { return force() * dx; }                        // N m per lattice unit
  double pressure() const { return rho * dx * dx / (dt * dt); }         // Pa per lattice unit
  double mach(double u_si) const { return u_si / velocity() * 1.7320508075688772; }  // u / c_s
};

}  // namespace lbdem
