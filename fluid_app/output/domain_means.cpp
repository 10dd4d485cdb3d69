#include "fluid_app/output/domain_means.hpp"

#include <algorithm>

namespace lbdem {

DomainMeans domain_means(const MacroFields& f, const UnitConverter& units, MPI_Comm comm) {
  // Lattice-unit sums of u, rho |u|^2 and rho, then one reduction for all of them.
  std::array<double, 5> sums{};
  double max_mach = 0;
  const std::size_t n = f.box.cells();
  for (std::size_t c = 0; c < n; ++c) {
    const double ux = f.u[3 * c], uy = f.u[3 * c + 1], uz = f.u[3 * c + 2];
    const double u2 = ux * ux + uy * uy + uz * uz;
    sums[0] += ux;
    sums[1] += uy;
    sums[2] += uz;
    sums[3] += f.rho[c] * u2;
    sums[4] += f.rho[c];
    max_mach = std::max(max_mach, std::sqrt(3.0 * u2));
  }
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), 5, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &max_mach, 1, MPI_DOUBLE, MPI_MAX, comm);
  const double cells = static_cast<double>(f.box.global_cells());
  DomainMeans m;
  for (int d = 0; d < 3; ++d) m.mean_velocity[d] = sums[d] / cells * units.velocity();
  const double v = units.velocity();
  m.kinetic_energy = 0.5 * sums[3] * units.rho * v * v * units.dx * units.dx * units.dx;
  m.mean_density = sums[4] / cells * units.rho;
  m.max_mach = max_mach;
  return m;
}

}  // namespace lbdem
