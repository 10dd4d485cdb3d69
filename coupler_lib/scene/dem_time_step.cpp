#include "coupler_lib/scene/dem_time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace lbdem {

double rayleigh_time(double radius, double density, const DemMaterial& m) {
  const double g = m.young_modulus / (2.0 * (1.0 + m.poisson_ratio));
  const double beta = 0.8766 + 0.1630 * m.poisson_ratio;
  return std::numbers::pi * radius / beta * std::sqrt(density / g);
}

double smallest_sphere_radius(const Shape& shape) {
  return *std::min_element(shape.clump.radii.begin(), shape.clump.radii.end());
}

double time_step_radius(const Shape& shape, const DemParams& params) {
  if (params.dt_rule == DtRule::particle)
    return std::cbrt(3.0 * shape.mass.volume / (4.0 * std::numbers::pi));
  return smallest_sphere_radius(shape);
}

double smallest_rayleigh_time(const DemParams& params, const std::vector<Shape>& shapes,
                              const std::vector<BodyParams>& bodies) {
  double t = std::numeric_limits<double>::infinity();
  for (const auto& b : bodies) {
    const Shape& sh = shapes[static_cast<size_t>(b.shape)];
    t = std::min(t, rayleigh_time(time_step_radius(sh, params), b.density, params.material));
  }
  return t;
}

double dem_time_step(const DemParams& params, const std::vector<Shape>& shapes,
                     const std::vector<BodyParams>& bodies) {
  if (params.dt > 0) return params.dt;
  return params.dt_fraction * smallest_rayleigh_time(params, shapes, bodies);
}

}  // namespace lbdem
