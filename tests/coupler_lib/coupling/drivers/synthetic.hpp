#pragma once
// Synthetic bodies and loads shared by the coupler test drivers (fluid_driver, dem_driver).
//
// Bodies follow deterministic trajectories that cross subdomain and periodic boundaries
// (the test scene has x and z periodic, walls in y); each fluid rank makes its partial load a known
// function of (body, fluid rank, step, the angular velocity it received), and the DEM side
// feeds the reduced torque back into the angular velocity, so a wrong or reordered load
// changes every later state.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/coupling/routing.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem::synthetic {

// Options a driver takes besides run_app's; they are removed from argv.
struct DriverOptions {
  std::int64_t throw_at_step = -1;     // throw a std::runtime_error at this step ...
  int throw_rank = 0;                  // ... on this rank
  bool exit_at_start = false;          // leave before the handshake, as a crash would
  std::int64_t finalize_at_step = -1;  // MPI_Finalize + exit(1) here, as LAMMPS's errors do
  bool finish_at_start = false;        // return normally without coupling (a program bug)
  std::uint32_t announce_version = kProtocolVersion;
  std::int64_t perturb_step = -1;  // change one packet by one ulp at this step
  std::int64_t steps = -1;         // run this many steps instead of the schedule's
  std::int64_t load_label = 0;     // label loads step + this (the fluid_app convention is 1)
};

inline DriverOptions take_driver_options(int& argc, char** argv) {
  DriverOptions o;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--throw-at-step")
      o.throw_at_step = std::stoll(value());
    else if (a == "--throw-rank")
      o.throw_rank = std::stoi(value());
    else if (a == "--finalize-at-step")
      o.finalize_at_step = std::stoll(value());
    else if (a == "--exit-at-start")
      o.exit_at_start = true;
    else if (a == "--finish-at-start")
      o.finish_at_start = true;
    else if (a == "--announce-version")
      o.announce_version = static_cast<std::uint32_t>(std::stoul(value()));
    else if (a == "--steps")
      o.steps = std::stoll(value());
    else if (a == "--load-label")
      o.load_label = std::stoll(value());
    else if (a == "--perturb-step")
      o.perturb_step = std::stoll(value());
    else
      argv[out++] = argv[i];
  }
  argc = out;
  return o;
}

inline double bounding_radius(const ShapeParams& s) {
  return s.kind == ShapeKind::cube ? 0.5 * s.size * std::sqrt(3.0) : 0.5 * s.size;
}

inline std::vector<double> shape_radii(const Scene& scene) {
  std::vector<double> r;
  for (const auto& s : scene.shapes) r.push_back(bounding_radius(s));
  return r;
}

inline std::array<bool, 3> periodic_axes(const Scene& scene) {
  return {scene.fluid->periodic(0), scene.fluid->periodic(1), scene.fluid->periodic(2)};
}

inline Box domain_box(const Scene& scene) {
  Box b;
  b.hi = scene.fluid->domain;
  return b;
}

// Uneven slabs of whole cells: 2 ranks split z, 3 split x, other counts split x.
inline Box fluid_box(const Scene& scene, int rank, int size) {
  Box b = domain_box(scene);
  const int axis = size == 2 ? 2 : 0;
  const int cells = scene.fluid->cells[static_cast<size_t>(axis)];
  const int base = cells / size, extra = cells % size;
  const int first = rank * base + std::min(rank, extra);
  const int count = base + (rank < extra ? 1 : 0);
  b.lo[static_cast<size_t>(axis)] = first * scene.fluid->dx;
  b.hi[static_cast<size_t>(axis)] = (first + count) * scene.fluid->dx;
  return b;
}

// Where body `id` is at `step`; w is left zero (the DEM driver integrates it).
inline BodyState trajectory(const Scene& scene, std::int64_t id, std::int64_t step) {
  const BodyParams& p = scene.bodies[static_cast<size_t>(id)];
  const auto& L = scene.fluid->domain;
  const double s = static_cast<double>(step), i = static_cast<double>(id);
  BodyState b;
  b.id = id;
  b.step = step;
  b.shape = p.shape;
  const double vx = 0.047 + 0.011 * i, vz = -0.031 + 0.007 * i;
  b.x[0] = p.position[0] + vx * s;
  b.x[1] = 0.5 * L[1] + 0.3 * L[1] * std::sin(0.2 * s + i);
  b.x[2] = p.position[2] + vz * s;
  if (id % 2 == 0)  // even bodies wrapped into the box, odd ones left unwrapped
    for (int d : {0, 2})
      b.x[d] -= L[static_cast<size_t>(d)] * std::floor(b.x[d] / L[static_cast<size_t>(d)]);
  const double a = 0.05 * s + i;
  b.q[0] = std::cos(a);
  b.q[1] = std::sin(a);
  b.v[0] = vx;
  b.v[1] = 0.06 * L[1] * std::cos(0.2 * s + i);
  b.v[2] = vz;
  return b;
}

// The partial load fluid rank `rank` reports for `b` at `step`.
inline BodyLoad partial(const BodyState& b, int rank, std::int64_t step) {
  BodyLoad l;
  l.id = b.id;
  l.step = step;
  const double i = static_cast<double>(b.id), r = rank, s = static_cast<double>(step);
  for (int k = 0; k < 3; ++k) {
    l.f[k] = 0.1 * (i + 1) + 0.37 * (r + 1) * (k + 1) + 1e-3 * s + b.w[k] / 3.0;
    l.t[k] = 0.01 * std::cos(i * k + r + s) + 0.5 * b.w[k];
  }
  return l;
}

// Independent of routing.cpp: explicit images along the periodic axes.
inline bool touches(const FluidLayout& layout, const Box& box, const double x[3], double reach) {
  for (int kx = -10; kx <= 10; ++kx)
    for (int kz = -10; kz <= 10; ++kz) {
      if ((kx && !layout.periodic[0]) || (kz && !layout.periodic[2])) continue;
      const int k[3] = {kx, 0, kz};
      double d2 = 0;
      for (int d = 0; d < 3; ++d) {
        const double len = layout.domain.hi[d] - layout.domain.lo[d];
        const double c = x[d] + k[d] * len;
        const double g = c < box.lo[d] ? box.lo[d] - c : (c > box.hi[d] ? c - box.hi[d] : 0.0);
        d2 += g * g;
      }
      if (d2 <= reach * reach) return true;
    }
  return false;
}

}  // namespace lbdem::synthetic
