#include "coupler_lib/scene/settling_balance.hpp"

namespace lbdem {

SettlingBalance settling_balance(const Scene& scene, const std::vector<Shape>& shapes) {
  SettlingBalance s;
  if (!scene.fluid || !scene.dem || scene.bodies.empty()) return s;
  const FluidParams& f = *scene.fluid;
  if (!(f.periodic(0) && f.periodic(1) && f.periodic(2))) return s;
  for (const auto& b : scene.bodies) {
    const double v = shapes[static_cast<size_t>(b.shape)].mass.volume;
    for (int a = 0; a < 3; ++a)
      s.net_weight[a] += (b.density - f.density) * v * scene.dem->gravity[a];
  }
  const double box = f.domain[0] * f.domain[1] * f.domain[2];
  for (int a = 0; a < 3; ++a) s.force_density[a] = -s.net_weight[a] / box;
  s.active = s.net_weight != std::array<double, 3>{};
  return s;
}

}  // namespace lbdem
