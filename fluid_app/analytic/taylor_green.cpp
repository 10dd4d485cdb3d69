#include "fluid_app/analytic/taylor_green.hpp"

#include <cmath>
#include <numbers>

namespace lbdem {

double TaylorGreen::wavenumber() const {
  return 2.0 * std::numbers::pi / period;
}

double TaylorGreen::velocity_decay(double t) const {
  const double k = wavenumber();
  return std::exp(-2.0 * nu * k * k * t);
}

std::array<double, 3> TaylorGreen::velocity(const std::array<double, 3>& x, double t) const {
  const double k = wavenumber();
  const double xa = k * x[plane[0]], xb = k * x[plane[1]];
  const double s = amplitude * velocity_decay(t);
  std::array<double, 3> u{};
  u[plane[0]] = s * std::sin(xa) * std::cos(xb);
  u[plane[1]] = -s * std::cos(xa) * std::sin(xb);
  return u;
}

double TaylorGreen::pressure(const std::array<double, 3>& x, double t) const {
  const double k = wavenumber();
  const double d = velocity_decay(t);
  return rho * amplitude * amplitude / 4.0 *
         (std::cos(2.0 * k * x[plane[0]]) + std::cos(2.0 * k * x[plane[1]])) * d * d;
}

}  // namespace lbdem
