// dem_bench: cost of the DEM side per step and per coupling exchange.
//
//   mpirun -np R build/tools/dem_bench [--cubes N] [--phi F] [--steps S] [--substeps n]
//
//   [--repeat K] [--lubrication H]
// N cubes (27-sphere clumps: 3x3x3 equal spheres of radius a/6) at solid fraction F
// in a triply periodic box, on a simple cubic lattice with random velocities and spins so
// that they collide from the start; the paper's contact parameters. Prints
//   1. DEM cost: seconds per step and atom-steps per second with `run S` in one call;
//   2. the same S steps in chunks of n substeps (as a coupled run does), without loads;
//   3. chunks of n with the exchange work: set_load on every owned body before each chunk
//      and owned_states after it (fix external with per-atom weights + per-atom torque),
//      and the bytes each rank received in the DEM ranks' load exchange per chunk (largest
//      and mean over ranks; LammpsEngine::load_traffic).
// 3 - 2 is the overhead of the external force/torque and state extraction per exchange.
// With --lubrication H (H: the cut-off gap h_c as a fraction of the cube edge), a fourth
// variant adds the sub-grid lubrication correction (docs/lubrication.md; mu = 1e-3 Pa s,
// h_min = h_c / 100) to 3; 4 - 3 is its cost.
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "coupler_lib/geometry/build_shape.hpp"
#include "dem_app/engine/lammps_engine.hpp"

namespace {

struct Options {
  long cubes = 1000;
  double phi = 0.3;
  long steps = 1000;
  long substeps = 10;
  int repeat = 2;
  double lubrication = 0;  // h_c / cube edge; 0: no lubrication variant
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i];
    const char* v = argv[i + 1];
    if (k == "--cubes")
      o.cubes = std::atol(v);
    else if (k == "--phi")
      o.phi = std::atof(v);
    else if (k == "--steps")
      o.steps = std::atol(v);
    else if (k == "--substeps")
      o.substeps = std::atol(v);
    else if (k == "--repeat")
      o.repeat = std::atoi(v);
    else if (k == "--lubrication")
      o.lubrication = std::atof(v);
    else
      throw std::invalid_argument(
          "unknown option " + k +
          " (known: --cubes --phi --steps --substeps --repeat --lubrication)");
  }
  if (o.cubes < 1 || !(o.phi > 0 && o.phi < 0.5) || o.steps < 1 || o.substeps < 1 || o.repeat < 1)
    throw std::invalid_argument("need cubes >= 1, 0 < phi < 0.5, steps >= 1, substeps >= 1");
  return o;
}

// A deterministic pseudo-random number in [-1, 1) from an index (SplitMix64 finaliser).
double noise(std::uint64_t i) {
  std::uint64_t z = i * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
}

lbdem::DemSetup make_setup(const Options& o, bool loads, bool lubrication) {
  const double a = 0.01;  // cube edge, m
  lbdem::ShapeParams p;
  p.name = "cube";
  p.kind = lbdem::ShapeKind::cube;
  p.size = a;
  p.where = "dem_bench";
  lbdem::DemSetup s;
  s.file = "dem_bench";
  s.params.gravity = {0, 0, 0};
  s.params.periodic = {true, true, true};
  // Mass properties from the voxelization; the clump is the classic 3x3x3 lattice of equal
  // spheres touching the faces (the shared notes' benchmark clump).
  lbdem::Shape cube = lbdem::build_shape(p, a / 20);
  cube.clump = {};
  for (int k = -1; k <= 1; ++k)
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) {
        cube.clump.centers.emplace_back(i * a / 3, j * a / 3, k * a / 3);
        cube.clump.radii.push_back(a / 6);
      }
  s.shapes.push_back(cube);
  // Cubic lattice, aligned cubes (spacing (a^3 / phi)^(1/3) > a keeps them apart).
  const auto n = static_cast<long>(std::ceil(std::cbrt(static_cast<double>(o.cubes))));
  const double spacing = a / std::cbrt(o.phi);
  const double side = spacing * static_cast<double>(n);
  s.box_lo = {0, 0, 0};
  s.box_hi = {side, side, side};
  for (long i = 0; i < o.cubes; ++i) {
    lbdem::BodyParams b;
    b.shape = 0;
    b.density = 2500;
    const long ix = i % n, iy = (i / n) % n, iz = i / (n * n);
    b.position = {(ix + 0.5) * spacing, (iy + 0.5) * spacing, (iz + 0.5) * spacing};
    for (int d = 0; d < 3; ++d) {
      b.velocity[d] = 0.2 * noise(6 * static_cast<std::uint64_t>(i) + d);
      b.angular_velocity[d] = 20.0 * noise(6 * static_cast<std::uint64_t>(i) + 3 + d);
    }
    s.bodies.push_back(b);
  }
  s.external_loads = loads || lubrication;
  if (lubrication) {
    auto& l = s.params.lubrication;
    l.enabled = true;
    l.cutoff = o.lubrication * a;
    l.min_gap = 0.01 * l.cutoff;
    l.viscosity = 1e-3;
  }
  return s;
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Wall time of `work`, the slowest rank's.
template <class F>
double timed(MPI_Comm comm, F&& work) {
  MPI_Barrier(comm);
  const double t0 = now();
  work();
  MPI_Barrier(comm);
  double t = now() - t0;
  MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, comm);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int rc = 0;
  try {
    const Options o = parse(argc, argv);
    const long chunks = (o.steps + o.substeps - 1) / o.substeps;
    const long steps = chunks * o.substeps;
    double atoms = 0;
    // Each variant starts from the same state and warms up identically, then is timed; the
    // variants are interleaved `repeat` times and the fastest of each is kept (the machine
    // is shared). In the exchange variant the time inside set_load + owned_states is summed
    // separately (rank 0's).
    enum Variant { kOneRun, kChunked, kExchange, kLubricated };
    double exchange_calls = 0;
    double bytes_max = 0, bytes_mean = 0, messages_max = 0;  // per chunk, exchange variant
    long lubrication_builds = 0;
    std::size_t lubrication_pairs = 0;
    auto variant = [&](Variant v) {
      lbdem::LammpsEngine e(MPI_COMM_WORLD, make_setup(o, v >= kExchange, v == kLubricated));
      atoms = 0;
      for (const auto& b : e.setup().bodies)
        atoms += static_cast<double>(e.setup().shapes[static_cast<size_t>(b.shape)].clump.size());
      e.run(100);  // warm-up: neighbour lists, first contacts
      double calls = 0;
      const lbdem::LoadTraffic before = e.load_traffic();
      const double t = timed(MPI_COMM_WORLD, [&] {
        if (v == kOneRun) {
          e.run(steps);
          return;
        }
        for (long c = 0; c < chunks; ++c) {
          if (v >= kExchange) {
            const double t0 = now();
            for (const auto& s : e.owned_states(c))
              e.set_load(s.id, Eigen::Vector3d(1e-4, 0, 0), Eigen::Vector3d(0, 0, 1e-7));
            calls += now() - t0;
          }
          e.run(o.substeps);
        }
      });
      if (v == kExchange) {
        exchange_calls = calls;
        const double n = static_cast<double>(chunks);
        double bytes = static_cast<double>(e.load_traffic().bytes - before.bytes) / n;
        double messages = static_cast<double>(e.load_traffic().messages - before.messages) / n;
        MPI_Allreduce(&bytes, &bytes_max, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        MPI_Allreduce(&bytes, &bytes_mean, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
        MPI_Allreduce(MPI_IN_PLACE, &messages, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
        bytes_mean /= size;
        messages_max = messages;
      }
      if (v == kLubricated) {
        lubrication_builds = e.lubrication().builds();
        lubrication_pairs = e.lubrication().pairs();
      }
      return t;
    };
    double t_one = 1e300, t_chunked = 1e300, t_exchange = 1e300, best_calls = 1e300,
           t_lubricated = 1e300;
    for (int r = 0; r < o.repeat; ++r) {
      t_one = std::min(t_one, variant(kOneRun));
      t_chunked = std::min(t_chunked, variant(kChunked));
      const double t = variant(kExchange);
      if (t < t_exchange) {
        t_exchange = t;
        best_calls = exchange_calls;
      }
      if (o.lubrication > 0) t_lubricated = std::min(t_lubricated, variant(kLubricated));
    }
    if (rank == 0) {
      const double per_step = t_one / static_cast<double>(steps);
      std::printf(
          "dem_bench: %ld cubes x 27 spheres (%.0f atoms), phi = %.2f, %d rank%s, %ld steps\n",
          o.cubes, atoms, o.phi, size, size > 1 ? "s" : "", steps);
      std::printf("  one run:                 %.4f s  %.3e s/step  %.3e atom-steps/s\n", t_one,
                  per_step, atoms * static_cast<double>(steps) / t_one);
      std::printf("  chunks of %ld, no loads:  %.4f s  (+%.3f ms per chunk)\n", o.substeps,
                  t_chunked, 1e3 * (t_chunked - t_one) / static_cast<double>(chunks));
      std::printf(
          "  chunks with exchange:    %.4f s  (+%.3f ms per exchange = %.1f %% of the "
          "chunk's DEM work)\n"
          "                           of which set_load + owned_states: %.3f ms per exchange, "
          "the rest is fix external in the steps\n",
          t_exchange, 1e3 * (t_exchange - t_chunked) / static_cast<double>(chunks),
          100.0 * (t_exchange - t_chunked) / t_chunked,
          1e3 * best_calls / static_cast<double>(chunks));
      std::printf(
          "  load exchange received per rank and chunk: %.0f bytes largest, %.0f mean, "
          "%.0f messages largest\n",
          bytes_max, bytes_mean, messages_max);
      if (o.lubrication > 0)
        std::printf(
            "  with lubrication (h_c = %.3g edge): %.4f s  (+%.1f %% over the exchange variant; "
            "rank 0: %ld list builds, %zu candidate pairs at the end)\n",
            o.lubrication, t_lubricated, 100.0 * (t_lubricated - t_exchange) / t_exchange,
            lubrication_builds, lubrication_pairs);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dem_bench: error: %s\n", e.what());
    rc = 1;
  }
  MPI_Finalize();
  return rc;
}
