#include "coupler_lib/scene/fluid_section.hpp"

#include <cmath>

namespace lbdem {

FluidParams parse_fluid(Section& s) {
  FluidParams p;
  p.domain = s.require_vec3("domain", "box size [Lx, Ly, Lz] in m", Bounds::positive());
  p.dx = s.require<double>("dx", "lattice spacing in m", Bounds::positive());
  p.density = s.get<double>("density", 1000.0, "fluid density in kg/m^3", Bounds::positive());
  p.viscosity = s.require<double>("viscosity", "kinematic viscosity in m^2/s", Bounds::positive());
  p.tau = s.get<double>("tau", 0.6, "BGK relaxation time", Bounds::above(0.5));
  p.precision = s.choice("precision", "double", {"double", "float"}, "floating-point type");
  for (int d = 0; d < 3; ++d) {
    const double n = p.domain[d] / p.dx;
    p.cells[d] = static_cast<int>(std::lround(n));
    if (p.cells[d] < 1 || std::abs(n - p.cells[d]) > 1e-6 * n)
      s.fail("domain", "domain size must be a whole number of cells of dx; got " +
                           std::to_string(n) + " cells along axis " + std::to_string(d));
  }
  p.units = UnitConverter::from_tau(p.dx, p.tau, p.viscosity, p.density);
  s.finish();
  return p;
}

}  // namespace lbdem
