#include "fluid_app/validation/velocity_error.hpp"

#include <algorithm>
#include <cmath>

namespace lbdem {

VelocityError velocity_error(const MacroFields& f, const UnitConverter& units,
                             const ReferenceSolution& ref, double time, MPI_Comm comm) {
  std::array<double, 2> sums{};  // sum |u - u_ref|^2, sum |u_ref|^2
  double max_abs = 0;
  const FieldBlock& b = f.box;
  const double v = units.velocity();
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        const std::array<double, 3> x{(b.lo[0] + i + 0.5) * units.dx,
                                      (b.lo[1] + j + 0.5) * units.dx,
                                      (b.lo[2] + k + 0.5) * units.dx};
        const std::array<double, 3> u_ref = ref.velocity(x, time);
        const std::size_t c = b.index(i, j, k);
        double diff2 = 0;
        for (int d = 0; d < 3; ++d) {
          const double e = f.u[3 * c + d] * v - u_ref[d];
          diff2 += e * e;
          sums[1] += u_ref[d] * u_ref[d];
        }
        sums[0] += diff2;
        max_abs = std::max(max_abs, std::sqrt(diff2));
      }
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), 2, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &max_abs, 1, MPI_DOUBLE, MPI_MAX, comm);
  VelocityError e;
  e.l2_relative = sums[1] > 0 ? std::sqrt(sums[0] / sums[1]) : std::sqrt(sums[0]);
  e.max_abs = max_abs;
  return e;
}

}  // namespace lbdem
