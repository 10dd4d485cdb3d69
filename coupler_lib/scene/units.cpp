#include "coupler_lib/scene/units.hpp"

namespace lbdem {

UnitConverter UnitConverter::from_tau(double dx, double tau, double nu, double rho) {
  UnitConverter u;
  u.dx = dx;
  u.tau = tau;
  u.nu = nu;
  u.rho = rho;
  u.dt = (tau - 0.5) * dx * dx / (3.0 * nu);
  return u;
}

}  // namespace lbdem
