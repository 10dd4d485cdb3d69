// porosity_bench: cost of the HLBM porosity update (fluid_app/hlbm/body_field) on a scene's
// bodies, for both porosity lookups.
//
//   porosity_bench scene.yaml [--updates 200] [--lookup trilinear|nearest|both]
//
// One fluid rank holding the whole lattice of the scene (no MPI traffic, no fluid step). The
// scene's bodies start at their scene poses and each moves by 0.03 cells and turns by 0.003
// rad per update in a fixed random direction (a settling suspension at lattice Mach ~0.05):
// every update is incremental. Prints, per lookup: band cells per body and per body volume
// (cells with 0 < d < 1 over the voxelized body volume in cells), evaluations per band cell, ns
// per band cell and per evaluation (CPU time of the thread), the cost of one full embedding for
// comparison, the cells found inside two bodies (interior conflicts: the bodies move without
// contacts and come to overlap), and a digest of the porosity field after every update (FNV-1a
// over d and the body index of every cell), to compare two builds bit for bit; where interiors
// overlap the field depends on which cells an update visits, so compare digests of runs without
// conflicts (fewer updates).
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "fluid_app/hlbm/body_field.hpp"

namespace {

using lbdem::BodyState;
using lbdem::PorosityLookup;
using namespace lbdem::hlbm;

// FNV-1a over the bytes of an array, continuing from h.
template <class V>
std::uint64_t fnv1a(std::uint64_t h, const V& values) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (std::size_t i = 0; i < values.size() * sizeof(values[0]); ++i)
    h = (h ^ bytes[i]) * 0x100000001b3ull;
  return h;
}

// CPU time of this thread: on a shared machine the wall time mostly measures the others.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Mover {
  Eigen::Vector3d x, v, w;  // m, m per update, rad per update
  Eigen::Quaterniond q;
};

void run(const lbdem::Scene& scene, const std::vector<lbdem::Shape>& shapes, PorosityLookup lookup,
         int updates) {
  const lbdem::FluidParams& fp = *scene.fluid;
  Subdomain sub;
  sub.box.n = fp.cells;
  sub.box.global = fp.cells;
  for (int a = 0; a < 3; ++a) sub.periodic[a] = fp.periodic(a);
  LatticeFrame frame{Eigen::Vector3d::Zero(), fp.units};
  lbdem::PorousField<double> field;
  BodyField<double> bodies(shapes, sub, frame, field, lookup);

  std::mt19937_64 rng(7);
  std::normal_distribution<double> g;
  std::vector<Mover> movers;
  double volume_cells = 0;
  for (const lbdem::BodyParams& b : scene.bodies) {
    Mover m;
    m.x = Eigen::Vector3d(b.position[0], b.position[1], b.position[2]);
    m.q =
        Eigen::Quaterniond(b.orientation[0], b.orientation[1], b.orientation[2], b.orientation[3]);
    m.v = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * 0.03 * fp.dx;
    m.w = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * 3e-3;
    movers.push_back(m);
    volume_cells += shapes[static_cast<std::size_t>(b.shape)].mass.volume / std::pow(fp.dx, 3);
  }
  std::vector<BodyState> states(movers.size());
  auto pack = [&]() {
    for (std::size_t k = 0; k < movers.size(); ++k) {
      BodyState& s = states[k];
      s.id = static_cast<std::int64_t>(k);
      s.shape = scene.bodies[k].shape;
      for (int a = 0; a < 3; ++a) s.x[a] = movers[k].x[a];
      s.q[0] = movers[k].q.w();
      s.q[1] = movers[k].q.x();
      s.q[2] = movers[k].q.y();
      s.q[3] = movers[k].q.z();
    }
  };
  auto advance = [&]() {
    for (Mover& m : movers) {
      m.x += m.v;
      m.q =
          (Eigen::Quaterniond(Eigen::AngleAxisd(m.w.norm(), m.w.normalized())) * m.q).normalized();
    }
  };

  pack();
  double t0 = cpu_seconds();
  const UpdateStats first = bodies.update(states);
  const double embed_s = cpu_seconds() - t0;
  std::size_t evaluated = 0, band = 0, scans = 0, conflicts = first.interior_conflicts;
  double update_s = 0;
  std::uint64_t digest = fnv1a(fnv1a(0xcbf29ce484222325ull, field.d), field.body);
  for (int k = 0; k < updates; ++k) {
    advance();
    pack();
    t0 = cpu_seconds();
    const UpdateStats s = bodies.update(states);
    update_s += cpu_seconds() - t0;
    evaluated += s.evaluated;
    band += s.band;
    scans += s.full_scans;
    conflicts += s.interior_conflicts;
    digest = fnv1a(fnv1a(digest, field.d), field.body);
  }
  const double n = static_cast<double>(movers.size());
  const double band_per_update = double(band) / updates;
  std::printf("  %-9s %6zu %10.0f %10.3f %9.2f %12.1f %12.1f %10.1f %12.1f %6zu %9zu  %016llx\n",
              lookup == PorosityLookup::nearest ? "nearest" : "trilinear", movers.size(),
              band_per_update / n, band_per_update / volume_cells, double(evaluated) / double(band),
              1e9 * update_s / double(band), 1e9 * update_s / double(evaluated),
              1e6 * update_s / updates, 1e9 * embed_s / double(first.evaluated), scans, conflicts,
              static_cast<unsigned long long>(digest));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr,
                 "usage: porosity_bench scene.yaml [--updates N] [--lookup "
                 "trilinear|nearest|both]\n");
    return 2;
  }
  int updates = 200;
  std::string which = "both";
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--updates" && i + 1 < argc) {
      updates = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--lookup" && i + 1 < argc) {
      which = argv[++i];
    } else {
      std::fprintf(stderr, "porosity_bench: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  try {
    const lbdem::Scene scene = lbdem::load_scene(argv[1]);
    if (!scene.fluid || scene.bodies.empty()) {
      std::fprintf(stderr, "porosity_bench: %s needs a fluid section and bodies\n", argv[1]);
      return 2;
    }
    const std::vector<lbdem::Shape> shapes = lbdem::build_scene_shapes(scene);
    const auto& c = scene.fluid->cells;
    std::printf("# porosity_bench %s: %d x %d x %d cells, %d updates (CPU time of the thread)\n",
                argv[1], c[0], c[1], c[2], updates);
    std::printf("# %-9s %6s %10s %10s %9s %12s %12s %10s %12s %6s %9s  %-16s\n", "lookup", "bodies",
                "band/body", "band/vol", "eval/band", "ns/band cell", "ns/eval", "us/update",
                "embed ns/ev", "scans", "conflicts", "field digest");
    if (which == "both" || which == "trilinear")
      run(scene, shapes, PorosityLookup::trilinear, updates);
    if (which == "both" || which == "nearest") run(scene, shapes, PorosityLookup::nearest, updates);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "porosity_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
