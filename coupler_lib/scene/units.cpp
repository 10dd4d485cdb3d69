#include "coupler_lib/scene/units.hpp"

#include <algorithm>
#include <cmath>

#include <spdlog/fmt/fmt.h>

namespace lbdem {

long steps_between(double interval, double dt) {
  return std::max(1L, std::lround(interval / dt));
}

UnitConverter UnitConverter::from_tau(double dx, double tau, double nu, double rho) {
  UnitConverter u;
  u.dx = dx;
  u.tau = tau;
  u.nu = nu;
  u.rho = rho;
  u.dt = (tau - 0.5) * dx * dx / (3.0 * nu);
  return u;
}

std::string UnitConverter::describe() const {
  std::string s = fmt::format(
      "lattice units: dx = {:.6g} m, dt = {:.6g} s, tau = {:.6g}, nu_lattice = {:.6g} "
      "(nu = {:.6g} m^2/s), rho = {:.6g} kg/m^3\n",
      dx, dt, tau, nu_lattice(), nu, rho);
  s += fmt::format(
      "scales per lattice unit: velocity {:.6g} m/s, acceleration {:.6g} m/s^2, force {:.6g} N, "
      "pressure {:.6g} Pa",
      velocity(), acceleration(), force(), pressure());
  if (char_velocity > 0) {
    s += fmt::format(
        "\nexpected flow: U = {:.6g} m/s = {:.6g} lattice, Mach = {:.4g}, Re = {:.6g} (L = {:.6g} "
        "m = {:.4g} cells)",
        char_velocity, char_velocity / velocity(), expected_mach(), expected_reynolds(),
        char_length, char_length / dx);
  } else {
    s += "\nexpected flow: not given (set fluid.characteristic_velocity to log Mach and Re)";
  }
  return s;
}

std::string UnitConverter::check(const UnitLimits& limits) const {
  std::string msg;
  if (tau < limits.min_tau)
    msg += fmt::format(
        "tau = {:.6g} is too close to 1/2 (minimum {:.4g}): the lattice viscosity {:.3g} is too "
        "small for BGK to stay stable. Raise fluid.tau, or refine dx (at fixed tau a smaller dx "
        "also shortens dt).",
        tau, limits.min_tau, nu_lattice());
  if (char_velocity > 0 && expected_mach() > limits.max_mach) {
    if (!msg.empty()) msg += "\n";
    // Ma = sqrt(3) U dt / dx with dt = (tau - 1/2) dx^2 / (3 nu): Ma scales as (tau - 1/2) dx.
    msg += fmt::format(
        "expected Mach number {:.4g} (U = {:.6g} m/s = {:.4g} lattice units) exceeds {:.3g}: "
        "compressibility errors dominate. Lower fluid.tau toward 0.5 or refine dx (both shrink "
        "dt and hence the lattice velocity); a Mach number below 0.1 is advisable.",
        expected_mach(), char_velocity, char_velocity / velocity(), limits.max_mach);
  }
  return msg;
}

}  // namespace lbdem
