#include "fluid_app/parallel/balance.hpp"

#include <cmath>

namespace lbdem {

std::array<std::vector<double>, 3> body_work_weights(const FluidParams& fluid,
                                                     const std::vector<BodyParams>& bodies,
                                                     const std::vector<Shape>& shapes) {
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kBandReach = 1.5;  // cells beyond the surface a body's band reaches
  const auto& n = fluid.cells;
  std::array<std::vector<double>, 3> w;
  for (int a = 0; a < 3; ++a)
    w[a].assign(std::size_t(n[a]), double(n[(a + 1) % 3]) * double(n[(a + 2) % 3]));
  const double extra = fluid.covered_cell_weight - 1;
  for (const BodyParams& b : bodies) {
    const double volume = shapes[std::size_t(b.shape)].mass.volume / std::pow(fluid.dx, 3);
    const double radius = std::cbrt(3 * volume / (4 * kPi)) + kBandReach;  // cells
    for (int a = 0; a < 3; ++a) {
      const double centre = b.position[a] / fluid.dx - 0.5;  // node i sits at (i + 1/2) dx
      for (int i = int(std::floor(centre - radius)); i <= int(std::ceil(centre + radius)); ++i) {
        const double x = double(i) - centre;
        const double area = kPi * (radius * radius - x * x);  // the sphere's cross-section
        if (area <= 0) continue;
        int cell = i;
        if (fluid.periodic(a))
          cell = ((i % n[a]) + n[a]) % n[a];
        else if (i < 0 || i >= n[a])
          continue;
        w[a][std::size_t(cell)] += extra * area;
      }
    }
  }
  return w;
}

}  // namespace lbdem
