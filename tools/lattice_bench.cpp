// lattice_bench: cost of the lattice step with a scene's bodies embedded against the same
// lattice without them, and a fingerprint of the state for bit-identity
// checks of kernel changes.
//
//   lattice_bench scene.yaml [--steps 200] [--repeat 3] [--force] [--fingerprint N]
//
// One rank holding the scene's whole lattice (no halo traffic to other ranks, no DEM). The
// bodies sit at their scene poses, each with a fixed velocity (0.01 lattice units) and spin
// (1e-4 rad per step) in a random direction, embedded once (the porosity update is
// tools/porosity_bench's business). --force adds a uniform force density of 1e-6 (lattice
// units) along -z, as the settling scenes' compensating force puts every row on the forced
// path. Each repetition times `steps` steps with the bodies, `steps` steps of a second
// solver without them (with the same force) and `steps` of a third without bodies or force, CPU
// time of the thread (immune to the shared load's scheduling, not to cache and memory-bandwidth
// sharing) and wall time.
//
// --only bodies|fluid: time only the solver with the bodies or the one without (for perf stat).
// --fingerprint N: run N steps with the bodies, then print a 64-bit FNV-1a hash of the interior
// populations and of the last step's per-body exchange sums (docs/method-loads.md), and the
// sums themselves. Two builds agree bit for bit iff the hashes agree.
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "fluid_app/hlbm/body_field.hpp"
#include "fluid_app/solver/fluid_solver.hpp"

namespace {

using namespace lbdem;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::uint64_t fnv(std::uint64_t h, const void* p, std::size_t n) {
  const auto* b = static_cast<const unsigned char*>(p);
  for (std::size_t k = 0; k < n; ++k) h = (h ^ b[k]) * 1099511628211ull;
  return h;
}

struct Timing {
  double cpu = 0, wall = 0;
};

// Cells per 512-bit vector in double: the porous kernel's cell loop takes this many per
// iteration (docs/performance.md, "The porous kernel").
constexpr int kVectorCells = 8;

// How the porous rows are made: rows with a covered cell (d < 1), those whose covered cells
// all belong to one body (the kernel broadcasts that body's parameters on them), and, on the
// porous rows, the vectors of the cell loop (kVectorCells cells from the row's start) that hold
// several bodies' covered cells or none.
struct RowComposition {
  std::size_t rows = 0, porous_rows = 0, one_body_rows = 0, covered_cells = 0;
  std::size_t vectors = 0, mixed_vectors = 0, fluid_vectors = 0;
};

RowComposition row_composition(const LocalBox& box, const PorousField<double>& field) {
  RowComposition c;
  const auto bodies_in = [&](int x0, int x1, int y, int z, std::int32_t& lo, std::int32_t& hi) {
    lo = std::numeric_limits<std::int32_t>::max();
    hi = -2;
    std::size_t n = 0;
    for (int x = x0; x < x1; ++x) {
      const CellIndex i = box.index(x, y, z);
      if (field.d[i] >= 1.0f) continue;
      ++n;
      lo = std::min(lo, field.body[i]);
      hi = std::max(hi, field.body[i]);
    }
    return n;
  };
  for (int z = 1; z <= box.n[2]; ++z)
    for (int y = 1; y <= box.n[1]; ++y) {
      ++c.rows;
      std::int32_t lo = 0, hi = 0;
      const std::size_t n = bodies_in(1, box.n[0] + 1, y, z, lo, hi);
      if (n == 0) continue;
      c.covered_cells += n;
      ++c.porous_rows;
      c.one_body_rows += lo == hi ? 1 : 0;
      for (int x = 1; x <= box.n[0]; x += kVectorCells) {
        ++c.vectors;
        const std::size_t m = bodies_in(x, std::min(x + kVectorCells, box.n[0] + 1), y, z, lo, hi);
        c.fluid_vectors += m == 0 ? 1 : 0;
        c.mixed_vectors += m > 0 && lo != hi ? 1 : 0;
      }
    }
  return c;
}

Timing time_steps(FluidSolver<double>& s, int steps) {
  const double c0 = cpu_seconds(), w0 = wall_seconds();
  for (int k = 0; k < steps; ++k) s.step();
  return {cpu_seconds() - c0, wall_seconds() - w0};
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  if (argc < 2) {
    std::fprintf(
        stderr,
        "usage: lattice_bench scene.yaml [--steps N] [--repeat R] [--force] [--only bodies|fluid] "
        "[--fingerprint N]\n");
    MPI_Finalize();
    return 2;
  }
  int steps = 200, repeat = 3, fingerprint = 0;
  bool force = false;
  std::string only;  // bodies | fluid: time only that solver (for perf stat)
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--steps" && i + 1 < argc) {
      steps = std::max(2, std::atoi(argv[++i]) / 2 * 2);
    } else if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--fingerprint" && i + 1 < argc) {
      fingerprint = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--only" && i + 1 < argc) {
      only = argv[++i];
    } else if (a == "--force") {
      force = true;
    } else {
      std::fprintf(stderr, "lattice_bench: unknown argument '%s'\n", a.c_str());
      MPI_Finalize();
      return 2;
    }
  }
  int rc = 0;
  try {
    const Scene scene = load_scene(argv[1]);
    if (!scene.fluid || scene.bodies.empty())
      throw std::runtime_error("the scene needs a fluid section and bodies");
    const std::vector<Shape> shapes = build_scene_shapes(scene);
    const FluidParams& fp = *scene.fluid;
    FluidSolver<double> with(fp, MPI_COMM_WORLD), without(fp, MPI_COMM_WORLD),
        plain(fp, MPI_COMM_WORLD);
    if (force) {
      with.set_uniform_force({0, 0, -1e-6});
      without.set_uniform_force({0, 0, -1e-6});
    }
    hlbm::Subdomain sub{with.box(), {fp.periodic(0), fp.periodic(1), fp.periodic(2)}};
    hlbm::LatticeFrame frame{Eigen::Vector3d::Zero(), fp.units};
    hlbm::BodyField<double> bodies(shapes, sub, frame, with.porous(), fp.porosity_lookup);
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g;
    std::vector<BodyState> states;
    for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
      const BodyParams& b = scene.bodies[k];
      BodyState s;
      s.id = static_cast<std::int64_t>(k);
      s.shape = b.shape;
      const Eigen::Vector3d v = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * 0.01;
      const Eigen::Vector3d w = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * 1e-4;
      for (int a = 0; a < 3; ++a) {
        s.x[a] = b.position[a];
        s.v[a] = v[a] * fp.units.velocity();
        s.w[a] = w[a] / fp.units.dt;
      }
      for (int a = 0; a < 4; ++a) s.q[a] = b.orientation[a];
      states.push_back(s);
    }
    const hlbm::UpdateStats st = bodies.update(states);
    const LocalBox& box = with.box();
    const RowComposition rc_rows = row_composition(box, with.porous());
    const double cells = double(box.interior_cells());
    std::printf(
        "# lattice_bench %s: %d x %d x %d cells, %zu bodies, band %zu cells, d < 1: %zu cells "
        "(%.1f %%), rows with d < 1: %.1f %%%s\n",
        argv[1], box.n[0], box.n[1], box.n[2], states.size(), st.band, rc_rows.covered_cells,
        100.0 * double(rc_rows.covered_cells) / cells,
        100.0 * double(rc_rows.porous_rows) / double(rc_rows.rows), force ? ", uniform force" : "");
    std::printf(
        "# rows with d < 1: %.1f %% of them with one body's cells only; vectors of %d cells on "
        "those rows: %.1f %% with several bodies' cells, %.1f %% without a cell of d < 1\n",
        100.0 * double(rc_rows.one_body_rows) /
            double(std::max<std::size_t>(rc_rows.porous_rows, 1)),
        kVectorCells,
        100.0 * double(rc_rows.mixed_vectors) / double(std::max<std::size_t>(rc_rows.vectors, 1)),
        100.0 * double(rc_rows.fluid_vectors) / double(std::max<std::size_t>(rc_rows.vectors, 1)));
    if (fingerprint > 0) {
      for (int k = 0; k < fingerprint; ++k) with.step();
      std::vector<double> pop;
      with.interior_populations(pop);
      const std::uint64_t hp = fnv(1469598103934665603ull, pop.data(), pop.size() * sizeof(double));
      std::uint64_t he = 1469598103934665603ull;
      for (const PenaltyExchange& e : with.porous().exchange) {
        he = fnv(he, e.impulse.data(), sizeof(e.impulse));
        he = fnv(he, e.moment.data(), sizeof(e.moment));
        he = fnv(he, e.covered.data(), sizeof(e.covered));
        he = fnv(he, e.covered_moment.data(), sizeof(e.covered_moment));
      }
      std::printf("fingerprint after %d steps: populations %016llx, exchange %016llx\n",
                  fingerprint, static_cast<unsigned long long>(hp),
                  static_cast<unsigned long long>(he));
      const PenaltyExchange& e = with.porous().exchange.front();
      std::printf("body 0: impulse %.17g %.17g %.17g covered %.17g %.17g %.17g\n", e.impulse[0],
                  e.impulse[1], e.impulse[2], e.covered[0], e.covered[1], e.covered[2]);
    } else if (!only.empty()) {
      FluidSolver<double>& s = only == "bodies" ? with : without;
      const Timing t = time_steps(s, steps * repeat);
      std::printf("%s: %.3f ms per step (CPU), %.3f (wall)\n", only.c_str(),
                  1e3 * t.cpu / (steps * repeat), 1e3 * t.wall / (steps * repeat));
    } else {
      time_steps(with, 2);
      time_steps(without, 2);
      time_steps(plain, 2);
      // CPU ms per step (wall ms per step): with the bodies, the same lattice without them
      // (with the force if --force), and without bodies or force (a fluid-only scene).
      std::printf("# %-4s %16s %16s %16s %13s %13s\n", "rep", "bodies", "no bodies", "plain",
                  "/ no bodies", "/ plain");
      for (int r = 0; r < repeat; ++r) {
        const Timing a = time_steps(with, steps);
        const Timing b = time_steps(without, steps);
        const Timing c = time_steps(plain, steps);
        std::printf(
            "  %-4d %7.3f (%6.3f) %7.3f (%6.3f) %7.3f (%6.3f) %5.3f (%5.3f) %5.3f (%5.3f)\n", r,
            1e3 * a.cpu / steps, 1e3 * a.wall / steps, 1e3 * b.cpu / steps, 1e3 * b.wall / steps,
            1e3 * c.cpu / steps, 1e3 * c.wall / steps, a.cpu / b.cpu, a.wall / b.wall,
            a.cpu / c.cpu, a.wall / c.wall);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lattice_bench: %s\n", e.what());
    rc = 2;
  }
  MPI_Finalize();
  return rc;
}
