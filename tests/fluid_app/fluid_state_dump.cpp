// Runs a small deterministic fluid case on any number of ranks and writes the complete state
// (all 19 populations of every cell in global order, the mean flow and the controlled force)
// as raw bytes, so that runs on different rank counts can be compared byte for byte.
// Both cases have a uniform force and two spinning porous bodies:
//   walls:    periodic x, wall and moving wall in y, pressure faces in z; the force under
//             mean-velocity control; one body across the periodic x face;
//   periodic: periodic on every axis, a fixed force, no mean-flow sums; both bodies across
//             the periodic y face and apart in x, so that a split in x gives a rank rows that
//             cross one body where the whole row crosses two: the kernel's porous rows must
//             round a covered cell the same either way (docs/performance.md, "The porous
//             kernel").
//
// usage: fluid_state_dump walls|periodic OUT.bin [DX DY DZ]   (process grid; 0 = automatic)
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "fluid_app/forcing/mean_flow_control.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"

using namespace lbdem;

namespace {

// A sphere of the porous field: its centre and the radius where d reaches 1.
struct Ball {
  std::array<double, 3> centre;
  double radius;
};

// Distance of node g from the centre, minimum image on axes of period > 0.
double distance(const Ball& ball, const int (&g)[3], const std::array<int, 3>& period) {
  double r[3];
  for (int k = 0; k < 3; ++k) {
    r[k] = std::abs(g[k] + 0.5 - ball.centre[k]);
    if (period[k] > 0) r[k] = std::min(r[k], period[k] - r[k]);
  }
  return std::hypot(r[0], r[1], r[2]);
}

void run(const char* file, bool walls, std::array<int, 3> dims) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const std::array<int, 3> N = walls ? std::array<int, 3>{13, 10, 10} : std::array{16, 12, 12};
  FluidParams p = testing_fluid::lattice_params(N[0], N[1], N[2], 0.7);
  if (walls) {
    p.faces[2].type = FaceType::wall;
    p.faces[3] = {FaceType::moving_wall, {0.03, 0, 0.01}, 0};
    p.faces[4] = {FaceType::pressure, {}, 1000.0 * 0.002};
    p.faces[5] = {FaceType::pressure, {}, -1000.0 * 0.001};
  }
  const std::array<int, 3> period = walls ? std::array{N[0], 0, 0} : N;
  p.body_force = {1e-5, 0, 0};
  p.control.enabled = true;
  p.control.target = {0.002, 0, 0};
  FluidSolver<double> s(p, MPI_COMM_WORLD, dims);
  // The control makes the kernel sum the mean flow, another instantiation of its cell loop:
  // the periodic case runs the one without.
  std::optional<MeanFlowControl<double>> control;
  if (walls) control.emplace(s, p);

  const LocalBox& b = s.box();
  PorousField<double>& pf = s.porous();
  // The spheres of d < 1 (node g at g + 1/2); d = 1 at `radius`, 0 one cell inside it.
  const std::array<Ball, 2> balls =
      walls ? std::array<Ball, 2>{Ball{{0.0, 5.0, 5.0}, 3.5}, Ball{{7.0, 4.0, 6.0}, 2.5}}
            : std::array<Ball, 2>{Ball{{4.0, 0.5, 6.0}, 3.5}, Ball{{12.0, 0.8, 5.5}, 3.5}};
  pf.bodies = {{walls ? std::array{0.5, 5.0, 5.0} : balls[0].centre,
                {0.01, 0.0, -0.01},
                {walls ? 0.0 : 0.01, 0.02, 0.01}},
               {balls[1].centre, {0.0, 0.02, 0.0}, {0.01, -0.02, 0.015}}};
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const int g[3] = {b.offset[0] + x - 1, b.offset[1] + y - 1, b.offset[2] + z - 1};
        const CellIndex c = b.index(x, y, z);
        s.set_equilibrium(c, 1 + 0.01 * testing_fluid::wave(g[0], g[1], g[2], 0),
                          {0.02 * testing_fluid::wave(g[0], g[1], g[2], 1),
                           0.02 * testing_fluid::wave(g[0], g[1], g[2], 2),
                           0.02 * testing_fluid::wave(g[0], g[1], g[2], 3)});
        for (int k = 0; k < 2; ++k) {
          const double r = distance(balls[std::size_t(k)], g, period);
          if (r < balls[std::size_t(k)].radius) {
            pf.d[c] = float(std::clamp(r - (balls[std::size_t(k)].radius - 1.0), 0.0, 1.0));
            pf.body[c] = k;
            break;
          }
        }
      }
  pf.active = true;
  for (int n = 0; n < 21; ++n) {
    s.step();
    if (control) control->after_step();
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
  const std::string scene = argc > 1 ? argv[1] : "";
  if ((argc != 3 && argc != 6) || (scene != "walls" && scene != "periodic")) {
    if (rank == 0)
      std::fprintf(stderr, "usage: fluid_state_dump walls|periodic OUT.bin [DX DY DZ]\n");
    MPI_Finalize();
    return 2;
  }
  std::array<int, 3> dims{0, 0, 0};
  if (argc == 6)
    for (int a = 0; a < 3; ++a) dims[a] = std::atoi(argv[3 + a]);
  run(argv[2], scene == "walls", dims);
  MPI_Finalize();
  return 0;
}
