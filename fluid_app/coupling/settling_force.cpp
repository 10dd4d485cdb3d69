#include "fluid_app/coupling/settling_force.hpp"

#include <spdlog/fmt/fmt.h>

namespace lbdem {

SettlingForce settling_force(const Scene& scene, const std::vector<Shape>& shapes) {
  SettlingForce s;
  const SettlingBalance b = settling_balance(scene, shapes);
  if (!b.active) return s;
  const FluidParams& f = *scene.fluid;
  const double node_volume = f.dx * f.dx * f.dx;
  for (int a = 0; a < 3; ++a)
    s.fluid_force_lattice[a] = b.force_density[a] * node_volume / f.units.force();
  s.net_weight = b.net_weight;
  s.active = true;
  s.description = fmt::format(
      "triply periodic box: bodies' net weight [{:.4g}, {:.4g}, {:.4g}] N is balanced by a "
      "uniform force density [{:.4g}, {:.4g}, {:.4g}] N/m^3 on the box ([{:.4g}, {:.4g}, {:.4g}] "
      "per node, lattice units) on every node, bodies included: each body receives its share "
      "through "
      "the penalization",
      b.net_weight[0], b.net_weight[1], b.net_weight[2], b.force_density[0], b.force_density[1],
      b.force_density[2], s.fluid_force_lattice[0], s.fluid_force_lattice[1],
      s.fluid_force_lattice[2]);
  return s;
}

}  // namespace lbdem
