// Runs a small deterministic fluid case on any number of ranks and writes the complete state
// (all 19 populations of every cell in global order, the mean flow and the controlled force)
// as raw bytes, so that runs on different rank counts can be compared byte for byte.
// The case mixes every feature: periodic x, wall and moving wall in y, pressure faces in z,
// a uniform force under mean-velocity control and porous bodies (one across the periodic face).
//
// usage: fluid_state_dump OUT.bin [DX DY DZ]   (process grid; 0 = automatic)
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fluid_app/forcing/mean_flow_control.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"

using namespace lbdem;

namespace {

void run(const char* file, std::array<int, 3> dims) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::array<int, 3> N = {13, 10, 10};
  FluidParams p = testing_fluid::lattice_params(N[0], N[1], N[2], 0.7);
  p.faces[2].type = FaceType::wall;
  p.faces[3] = {FaceType::moving_wall, {0.03, 0, 0.01}, 0};
  p.faces[4] = {FaceType::pressure, {}, 1000.0 * 0.002};
  p.faces[5] = {FaceType::pressure, {}, -1000.0 * 0.001};
  p.body_force = {1e-5, 0, 0};
  p.control.enabled = true;
  p.control.target = {0.002, 0, 0};
  FluidSolver<double> s(p, MPI_COMM_WORLD, dims);
  MeanFlowControl<double> control(s, p);

  const LocalBox& b = s.box();
  PorousField<double>& pf = s.porous();
  pf.bodies = {{{0.5, 5.0, 5.0}, {0.01, 0.0, -0.01}, {0.0, 0.02, 0.01}},
               {{7.0, 4.0, 6.0}, {0.0, 0.02, 0.0}, {0.01, -0.02, 0.015}}};
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const int g[3] = {b.offset[0] + x - 1, b.offset[1] + y - 1, b.offset[2] + z - 1};
        const CellIndex c = b.index(x, y, z);
        s.set_equilibrium(c, 1 + 0.01 * testing_fluid::wave(g[0], g[1], g[2], 0),
                          {0.02 * testing_fluid::wave(g[0], g[1], g[2], 1),
                           0.02 * testing_fluid::wave(g[0], g[1], g[2], 2),
                           0.02 * testing_fluid::wave(g[0], g[1], g[2], 3)});
        const double r0 =
            std::hypot(std::min(g[0] + 0.5, N[0] - g[0] - 0.5), g[1] - 4.5, g[2] - 4.5);
        const double r1 = std::hypot(g[0] - 6.5, g[1] - 3.5, g[2] - 5.5);
        if (r0 < 3.5) {
          pf.d[c] = float(std::clamp(r0 - 2.5, 0.0, 1.0));
          pf.body[c] = 0;
        } else if (r1 < 2.5) {
          pf.d[c] = float(std::clamp(r1 - 1.5, 0.0, 1.0));
          pf.body[c] = 1;
        }
      }
  pf.active = true;
  for (int n = 0; n < 21; ++n) {
    s.step();
    control.after_step();
  }

  const std::size_t cells = std::size_t(N[0]) * N[1] * N[2];
  std::vector<double> local(cells * 19, 0.0), global(rank == 0 ? cells * 19 : 0);
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const std::size_t g =
            std::size_t(b.offset[0] + x - 1) +
            N[0] * (std::size_t(b.offset[1] + y - 1) + N[1] * std::size_t(b.offset[2] + z - 1));
        for (int i = 0; i < 19; ++i) local[g * 19 + i] = s.population(i, b.index(x, y, z));
      }
  // Each value is owned by one rank and zero elsewhere: the sum is exact.
  MPI_Reduce(local.data(), global.data(), int(local.size()), MPI_DOUBLE, MPI_SUM, 0,
             MPI_COMM_WORLD);
  if (rank == 0) {
    std::FILE* out = std::fopen(file, "wb");
    if (!out) {
      std::fprintf(stderr, "cannot write %s\n", file);
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    const MeanFlow m = s.mean_flow();
    const auto f = s.uniform_force();
    std::fwrite(global.data(), sizeof(double), global.size(), out);
    std::fwrite(m.velocity.data(), sizeof(double), 3, out);
    std::fwrite(f.data(), sizeof(double), 3, out);
    std::fclose(out);
    const auto& d = s.decomposition().dims();
    std::printf("wrote %s (process grid %d x %d x %d, mean u_x %.6e, force %.6e)\n", file, d[0],
                d[1], d[2], m.velocity[0], f[0]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (argc != 2 && argc != 5) {
    if (rank == 0) std::fprintf(stderr, "usage: fluid_state_dump OUT.bin [DX DY DZ]\n");
    MPI_Finalize();
    return 2;
  }
  std::array<int, 3> dims{0, 0, 0};
  if (argc == 5)
    for (int a = 0; a < 3; ++a) dims[a] = std::atoi(argv[2 + a]);
  run(argv[1], dims);
  MPI_Finalize();
  return 0;
}
