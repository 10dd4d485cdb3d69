// Moving bodies on the real solver, split over the ranks of MPI_COMM_WORLD (process grid
// from the command line, uneven blocks), against the same run on one rank (rank 0 runs it
// on MPI_COMM_SELF alongside): at every step the partial loads of all ranks must add up to
// the one-rank loads, and the porosity of every interior cell must match. The bodies
// rotate and translate across rank boundaries and across a periodic face.
//
// usage: hlbm_rank_loads DX DY DZ      (process grid; 0 = automatic). Exit status 0 = pass.
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <vector>

#include "fluid_app/coupling/solver_binding.hpp"
#include "fluid_app/hlbm/body_field.hpp"
#include "fluid_app/hlbm/momentum_exchange.hpp"
#include "fluid_app/hlbm/penalty_loads.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"
#include "tests/fluid_app/hlbm/hlbm_fixtures.hpp"

using namespace lbdem;

namespace {

std::vector<BodyState> poses(int step) {
  const double t = step;
  const Eigen::Quaterniond spin(Eigen::AngleAxisd(0.03 * t, Eigen::Vector3d(1, 2, 1).normalized()));
  return {hlbm::test::state(4, Eigen::Vector3d(21.5 + 0.15 * t, 9.2, 9.6), spin,
                            Eigen::Vector3d(0.15, 0, 0), Eigen::Vector3d(0.01, 0.02, 0.01), 0),
          hlbm::test::state(2, Eigen::Vector3d(8.3, 9.0 + 0.1 * t, 10.1), {1, 0, 0, 0},
                            Eigen::Vector3d(0, 0.1, 0), Eigen::Vector3d::Zero(), 1)};
}

struct Run {
  FluidParams p;
  FluidSolver<double> solver;
  hlbm::BodyField<double> bodies;
  hlbm::PenaltyLoads<double> loads;
  Run(const FluidParams& params, MPI_Comm comm, std::array<int, 3> dims, const Shape* shapes)
      : p(params),
        solver(p, comm, dims),
        bodies({shapes, 2}, hlbm::subdomain_of(solver, p), {Eigen::Vector3d::Zero(), p.units},
               solver.porous()) {
    solver.set_uniform_force({2e-5, -1e-5, 0});
  }
  // Loads of this rank, by body id: momentum exchange (force, torque), then the
  // penalization's (force, torque; its Q^{n-1} is per rank, so the sum tests that too).
  std::map<std::int64_t, std::array<double, 12>> step(int k) {
    const auto states = poses(k);
    bodies.update(states);
    solver.step();
    std::map<std::int64_t, std::array<double, 12>> out;
    auto put = [&](const BodyLoad& l, int at) {
      for (int c = 0; c < 3; ++c) {
        out[l.id][at + c] = l.f[c];
        out[l.id][at + 3 + c] = l.t[c];
      }
    };
    for (const BodyLoad& l : hlbm::momentum_exchange(bodies, hlbm::populations_of(solver), k))
      put(l, 0);
    for (const BodyLoad& l : loads.loads(bodies, k)) put(l, 6);
    return out;
  }
};

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::array<int, 3> dims = {0, 0, 0};
  for (int a = 0; a < 3 && a + 1 < argc; ++a) dims[a] = std::atoi(argv[a + 1]);

  const Shape shapes[2] = {hlbm::test::cube(6, 0.5), hlbm::test::sphere(3.5, 0.5)};
  const FluidParams p = testing_fluid::lattice_params(25, 19, 18, 0.8);
  Run parallel(p, MPI_COMM_WORLD, dims, shapes);
  std::unique_ptr<Run> serial;
  if (rank == 0)
    serial = std::make_unique<Run>(p, MPI_COMM_SELF, std::array<int, 3>{1, 1, 1}, shapes);
  double worst = 0;
  int bad_cells = 0;
  for (int k = 0; k < 60; ++k) {
    const auto mine = parallel.step(k);
    // Sum the partial loads of bodies 2 and 4 over the ranks (absent = 0).
    std::array<double, 24> part{}, total{};
    for (int b = 0; b < 2; ++b) {
      const auto it = mine.find(b == 0 ? 2 : 4);
      if (it != mine.end()) std::copy(it->second.begin(), it->second.end(), part.begin() + 12 * b);
    }
    MPI_Reduce(part.data(), total.data(), 24, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    // Porosity of this rank's interior cells against the serial field (gathered at rank 0).
    const auto& box = parallel.solver.box();
    std::vector<double> cells;  // global index, d
    for (int z = 1; z <= box.n[2]; ++z)
      for (int y = 1; y <= box.n[1]; ++y)
        for (int x = 1; x <= box.n[0]; ++x) {
          const int g =
              (box.offset[0] + x - 1) +
              p.cells[0] * ((box.offset[1] + y - 1) + p.cells[1] * (box.offset[2] + z - 1));
          cells.push_back(g);
          cells.push_back(parallel.bodies.field().d[static_cast<std::size_t>(box.index(x, y, z))]);
        }
    int count = static_cast<int>(cells.size());
    std::vector<int> counts(size), displs(size);
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<double> all;
    if (rank == 0) {
      for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
      all.resize(static_cast<std::size_t>(displs[size - 1] + counts[size - 1]));
    }
    MPI_Gatherv(cells.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (rank != 0) continue;
    const auto ref = serial->step(k);
    const auto& sb = serial->solver.box();
    for (std::size_t i = 0; i < all.size(); i += 2) {
      const int g = static_cast<int>(all[i]);
      const int x = g % p.cells[0], y = (g / p.cells[0]) % p.cells[1],
                z = g / (p.cells[0] * p.cells[1]);
      bad_cells +=
          serial->bodies.field().d[static_cast<std::size_t>(sb.index(x + 1, y + 1, z + 1))] !=
          static_cast<float>(all[i + 1]);
    }
    for (int b = 0; b < 2; ++b)
      for (int method = 0; method < 2; ++method) {
        const auto& r = ref.at(b == 0 ? 2 : 4);
        double scale = 0, diff = 0;
        for (int c = 6 * method; c < 6 * method + 6; ++c) {
          scale = std::max(scale, std::abs(r[c]));
          diff = std::max(diff, std::abs(total[12 * b + c] - r[c]));
        }
        worst = std::max(worst, diff / std::max(scale, 1e-300));
      }
    if (k == 59)
      std::printf("step %d: body 4 F = (%.4e %.4e %.4e), body 2 F = (%.4e %.4e %.4e)\n", k,
                  ref.at(4)[0], ref.at(4)[1], ref.at(4)[2], ref.at(2)[0], ref.at(2)[1],
                  ref.at(2)[2]);
  }
  int failed = 0;
  if (rank == 0) {
    std::printf(
        "%d ranks, grid %d %d %d: worst relative load difference %.2e, porosity "
        "mismatches %d\n",
        size, dims[0], dims[1], dims[2], worst, bad_cells);
    failed = (worst > 1e-9 || bad_cells != 0) ? 1 : 0;
  }
  MPI_Bcast(&failed, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Finalize();
  return failed;
}
