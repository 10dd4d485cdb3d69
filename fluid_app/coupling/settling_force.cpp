#include "fluid_app/coupling/settling_force.hpp"

#include <spdlog/fmt/fmt.h>

namespace lbdem {

SettlingForce settling_force(const Scene& scene, const std::vector<Shape>& shapes) {
  SettlingForce s;
  if (!scene.fluid || !scene.dem || scene.bodies.empty()) return s;
  const FluidParams& f = *scene.fluid;
  if (!(f.periodic(0) && f.periodic(1) && f.periodic(2))) return s;
  for (const auto& b : scene.bodies) {
    const double v = shapes[static_cast<size_t>(b.shape)].mass.volume;
    for (int a = 0; a < 3; ++a)
      s.net_weight[a] += (b.density - f.density) * v * scene.dem->gravity[a];
  }
  const double cells = double(f.cells[0]) * f.cells[1] * f.cells[2];
  for (int a = 0; a < 3; ++a) s.fluid_force_lattice[a] = -s.net_weight[a] / f.units.force() / cells;
  s.active = s.net_weight != std::array<double, 3>{};
  s.description = fmt::format(
      "triply periodic box: bodies' net weight [{:.4g}, {:.4g}, {:.4g}] N is balanced by a "
      "uniform fluid force [{:.4g}, {:.4g}, {:.4g}] per cell (lattice units)",
      s.net_weight[0], s.net_weight[1], s.net_weight[2], s.fluid_force_lattice[0],
      s.fluid_force_lattice[1], s.fluid_force_lattice[2]);
  return s;
}

}  // namespace lbdem
