#pragma once
// The decaying Taylor-Green vortex array, an exact solution of the incompressible
// Navier-Stokes equations in a periodic square of side L (k = 2 pi / L), here lying in the
// plane of two axes (a, b) of the 3D lattice and uniform along the third:
//   u_a =  U sin(k x_a) cos(k x_b) e^{-2 nu k^2 t}
//   u_b = -U cos(k x_a) sin(k x_b) e^{-2 nu k^2 t}
//   p   = rho U^2 / 4 (cos 2 k x_a + cos 2 k x_b) e^{-4 nu k^2 t}   (relative to the mean)
#include <array>

namespace lbdem {

struct TaylorGreen {
  double amplitude = 0;  // U, m/s
  double period = 1;     // L, m (the box side in both plane axes)
  double nu = 1e-6;      // m^2/s
  double rho = 1000;     // kg/m^3
  std::array<int, 2> plane{0, 1};

  double wavenumber() const;
  double velocity_decay(double t) const;  // e^{-2 nu k^2 t}
  std::array<double, 3> velocity(const std::array<double, 3>& x, double t) const;
  double pressure(const std::array<double, 3>& x, double t) const;
};

}  // namespace lbdem
