// fluid_bench: MLUPS of the D3Q19 kernel against the machine's memory-bandwidth roofline.
//
//   mpirun -np 1 fluid_bench [--sizes 64,128,192] [--seconds 1.5] [--porous [--phi 0.034]]
//
// For each lattice size and both precisions it runs the solver on a triply periodic box
// (all ranks of MPI_COMM_WORLD), and prints one line: precision, variant, MLUPS, bytes per
// cell update, and the fraction of the roofline. --porous adds the HLBM variant (porosity
// field with moving, spinning spherical bodies, solid fraction --phi, default 0.034; --phi 0
// keeps the porous field active with no body cell). The roofline is measured in the same run:
// a STREAM-copy loop over arrays far larger than the caches, on all ranks at once, gives the
// copy bandwidth B (bytes read + written per second, all ranks together); the roofline is
// B / (bytes per cell update) cell updates per second. The last column divides by an
// in-place update loop's bandwidth instead (the AA kernel's pattern, no write-allocate).
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "fluid_app/solver/fluid_solver.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Bandwidth of all ranks together in bytes/s (8 B read + 8 B written per element): best of
// several repetitions over 2 x 256 MiB per rank, every rank at the same time.
//   copy:     b[i] = a[i]           (STREAM copy; with ordinary stores the hardware also reads
//                                    b before writing it: write-allocate)
//   in place: a[i] = 1.5 a[i] + 1   (reads and writes the same lines, no write-allocate: the
//                                    access pattern of the AA kernel)
struct Bandwidth {
  double copy = 0, in_place = 0;
};

Bandwidth measure_bandwidth(MPI_Comm comm) {
  const std::size_t n = std::size_t(32) << 20;  // doubles per array
  std::unique_ptr<double[]> a(new double[n]), b(new double[n]);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = double(i % 7);
    b[i] = 0;
  }
  double best = 1e30, best_in_place = 1e30;
  for (int rep = 0; rep < 6; ++rep) {
    double* __restrict pa = a.get();
    double* __restrict pb = b.get();
    MPI_Barrier(comm);
    auto t0 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) pb[i] = pa[i];
    double t = seconds_since(t0), tmax = 0;
    MPI_Allreduce(&t, &tmax, 1, MPI_DOUBLE, MPI_MAX, comm);
    if (pb[n / 3] != pa[n / 3]) std::abort();  // keep the copy alive
    best = std::min(best, tmax);
    MPI_Barrier(comm);
    t0 = Clock::now();
    for (std::size_t i = 0; i < n; ++i) pa[i] = 1.5 * pa[i] + 1.0;
    t = seconds_since(t0);
    MPI_Allreduce(&t, &tmax, 1, MPI_DOUBLE, MPI_MAX, comm);
    if (!(pa[n / 3] > 0)) std::abort();
    best_in_place = std::min(best_in_place, tmax);
  }
  int size = 1;
  MPI_Comm_size(comm, &size);
  const double bytes = 2.0 * sizeof(double) * double(n) * size;
  return {bytes / best, bytes / best_in_place};
}

lbdem::FluidParams cube(int n) {
  lbdem::FluidParams p;
  p.cells = {n, n, n};
  p.dx = 1;
  p.domain = {double(n), double(n), double(n)};
  p.tau = 0.8;
  p.viscosity = 0.1;
  p.units = lbdem::UnitConverter::from_tau(1, 0.8, 0.1, 1000);
  return p;
}

// Million lattice updates per second of the whole domain.
template <class T>
double mlups(int n, bool porous, double phi, double seconds, MPI_Comm comm) {
  lbdem::FluidSolver<T> s(cube(n), comm);
  if (porous) {
    // Spheres on a 32-cell grid, radius (3 phi / 4 pi)^(1/3) 32 cells (phi = 0.034: 6.4 cells,
    // 13 % of the rows cross a body), each a body moving and spinning: the HLBM situation of
    // a suspension. Rows without a body cell take the plain forced path.
    const double radius = 32.0 * std::cbrt(3.0 * phi / (4.0 * std::numbers::pi));
    lbdem::PorousField<T>& pf = s.porous();
    const lbdem::LocalBox& b = s.box();
    const int per = std::max(1, n / 32);
    for (int k = 0; k < per * per * per; ++k) {
      const T c[3] = {T(16 + 32 * (k % per)), T(16 + 32 * ((k / per) % per)),
                      T(16 + 32 * (k / (per * per)))};
      pf.bodies.push_back({{c[0], c[1], c[2]}, {T(1e-3), 0, T(-2e-3)}, {0, T(1e-4), 0}});
    }
    for (int z = 1; z <= b.n[2]; ++z)
      for (int y = 1; y <= b.n[1]; ++y)
        for (int x = 1; x <= b.n[0]; ++x) {
          const int g[3] = {b.offset[0] + x - 1, b.offset[1] + y - 1, b.offset[2] + z - 1};
          double r2 = 0;
          for (int a = 0; a < 3; ++a) r2 += (g[a] % 32 + 0.5 - 16) * (g[a] % 32 + 0.5 - 16);
          const double d = std::clamp(std::sqrt(r2) - radius + 0.5, 0.0, 1.0);
          if (d < 1) {
            const lbdem::CellIndex cell = b.index(x, y, z);
            pf.d[cell] = float(d);
            pf.body[cell] = g[0] / 32 + per * (g[1] / 32 + per * (g[2] / 32));
          }
        }
    pf.active = true;
  }
  for (int k = 0; k < 2; ++k) s.step();
  // Pick an even number of steps that lasts about `seconds` (decided on rank 0).
  MPI_Barrier(comm);
  auto t0 = Clock::now();
  for (int k = 0; k < 2; ++k) s.step();
  double per_step = seconds_since(t0) / 2;
  MPI_Bcast(&per_step, 1, MPI_DOUBLE, 0, comm);
  const int steps = std::max(2, 2 * int(std::ceil(seconds / per_step / 2)));
  MPI_Barrier(comm);
  t0 = Clock::now();
  for (int k = 0; k < steps; ++k) s.step();
  double t = seconds_since(t0), tmax = 0;
  MPI_Allreduce(&t, &tmax, 1, MPI_DOUBLE, MPI_MAX, comm);
  return double(n) * n * n * steps / tmax * 1e-6;
}

std::vector<int> parse_sizes(const std::string& s) {
  std::vector<int> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(std::atoi(item.c_str()));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::vector<int> sizes = {64, 128, 192};
  double seconds = 1.5;
  bool porous = false;
  double phi = 0.034;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--sizes" && i + 1 < argc) {
      sizes = parse_sizes(argv[++i]);
    } else if (a == "--seconds" && i + 1 < argc) {
      seconds = std::atof(argv[++i]);
    } else if (a == "--porous") {
      porous = true;
    } else if (a == "--phi" && i + 1 < argc) {
      phi = std::atof(argv[++i]);
    } else {
      if (rank == 0)
        std::fprintf(stderr,
                     "usage: fluid_bench [--sizes 64,128,192] [--seconds S] [--porous [--phi "
                     "F]]\n");
      MPI_Finalize();
      return 2;
    }
  }
  const Bandwidth bwm = measure_bandwidth(MPI_COMM_WORLD);
  const double bw = bwm.copy;
  if (rank == 0) {
    std::printf(
        "# fluid_bench: D3Q19 BGK, AA pattern, %d rank(s); bandwidth (read + write, all "
        "ranks): copy %.2f GB/s, in-place update %.2f GB/s\n",
        size, bw * 1e-9, bwm.in_place * 1e-9);
    std::printf("# %-5s %-6s %-8s %-6s %9s %8s %11s %9s %11s\n", "ranks", "size", "prec", "kernel",
                "MLUPS", "B/cell", "roof MLUPS", "roof %", "in-place %");
  }
  for (int n : sizes)
    for (int prec = 0; prec < 2; ++prec)
      for (int v = 0; v < (porous ? 2 : 1); ++v) {
        const bool por = v == 1;
        const double m = prec == 0 ? mlups<double>(n, por, phi, seconds, MPI_COMM_WORLD)
                                   : mlups<float>(n, por, phi, seconds, MPI_COMM_WORLD);
        const int bytes = prec == 0 ? lbdem::FluidSolver<double>::bytes_per_cell_update(por)
                                    : lbdem::FluidSolver<float>::bytes_per_cell_update(por);
        const double roof = bw / bytes * 1e-6;
        if (rank == 0)
          std::printf("  %-5d %-6d %-8s %-6s %9.1f %8d %11.1f %8.1f%% %10.1f%%\n", size, n,
                      prec == 0 ? "double" : "float", por ? "hlbm" : "plain", m, bytes, roof,
                      100 * m / roof, 100 * m / (bwm.in_place / bytes * 1e-6));
        std::fflush(stdout);
      }
  MPI_Finalize();
  return 0;
}
