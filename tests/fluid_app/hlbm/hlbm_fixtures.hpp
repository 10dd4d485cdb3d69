#pragma once
// Shapes, boxes and population arrays for the HLBM tests, built here so the tests do not
// depend on the shape catalogue's builders: analytic voxelizations with the centroid at the
// origin, lattice units with dx = 1 m and dt = 1 s unless a test says otherwise.
#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/voxelize.hpp"
#include "fluid_app/hlbm/body_field.hpp"
#include "fluid_app/hlbm/momentum_exchange.hpp"
#include "fluid_app/hlbm/penalty_loads.hpp"
#include "fluid_app/lattice/d3q19.hpp"

namespace lbdem::hlbm::test {

// Voxels of spacing h over a cube of `half` voxels each side of the origin (voxel centres at
// h * (i - (n-1)/2)), solid (fill 1) where inside(centre).
inline Voxels voxelize(double h, int n, const std::function<bool(const Eigen::Vector3d&)>& in) {
  Voxels v;
  v.h = h;
  v.n = {n, n, n};
  v.origin = Eigen::Vector3d::Constant(-h * (n - 1) / 2.0);
  v.solid.assign(static_cast<std::size_t>(n) * n * n, 0);
  std::size_t idx = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i, ++idx)
        v.solid[idx] = in(v.origin + h * Eigen::Vector3d(i, j, k)) ? 1 : 0;
  v.fill.assign(v.solid.begin(), v.solid.end());
  return v;
}

// The fluid's reference lattice as the scenes build it (coupler_lib/geometry/shape.hpp): the
// stencil spacing h given, voxels of h / 2 holding the fill of a box h (box_averaged), so the
// lookup's stencil spans two voxels per c_i. (BodyField also takes voxels of h, a stencil of
// one voxel.)
inline Voxels reference_lattice(double h, int n,
                                const std::function<bool(const Eigen::Vector3d&)>& in) {
  return box_averaged(voxelize(h / 2, 2 * n, in));
}

inline Shape sphere(double radius, double h) {
  Shape s;
  s.name = "sphere";
  const int n = 2 * static_cast<int>(std::ceil(radius / h)) + 4;
  s.voxels = reference_lattice(h, n, [&](const Eigen::Vector3d& p) { return p.norm() < radius; });
  s.bounding_radius = radius;
  return s;
}

inline Shape cube(double edge, double h) {
  Shape s;
  s.name = "cube";
  const int n = 2 * static_cast<int>(std::ceil(edge / (2 * h))) + 4;
  s.voxels = reference_lattice(
      h, n, [&](const Eigen::Vector3d& p) { return p.cwiseAbs().maxCoeff() < edge / 2; });
  s.bounding_radius = edge * std::sqrt(3.0) / 2;
  return s;
}

// A block of `n` cells starting at global `offset` of a `global` lattice.
inline Subdomain subdomain(std::array<int, 3> global, std::array<int, 3> offset,
                           std::array<int, 3> n,
                           std::array<bool, 3> periodic = {true, true, true}) {
  Subdomain s;
  s.box.global = global;
  s.box.offset = offset;
  s.box.n = n;
  s.periodic = periodic;
  return s;
}
inline Subdomain whole(int n) {
  return subdomain({n, n, n}, {0, 0, 0}, {n, n, n});
}

// dx = 1 m, dt = 1 s, rho = 1: lattice and SI units coincide.
inline LatticeFrame unit_frame() {
  LatticeFrame f;
  f.units.dx = 1;
  f.units.dt = 1;
  f.units.rho = 1;
  f.units.tau = 1;
  f.units.nu = 1.0 / 6.0;
  return f;
}

inline BodyState state(std::int64_t id, Eigen::Vector3d x, Eigen::Quaterniond q = {1, 0, 0, 0},
                       Eigen::Vector3d v = Eigen::Vector3d::Zero(),
                       Eigen::Vector3d w = Eigen::Vector3d::Zero(), int shape = 0) {
  BodyState s;
  s.id = id;
  s.shape = shape;
  for (int a = 0; a < 3; ++a) {
    s.x[a] = x[a];
    s.v[a] = v[a];
    s.w[a] = w[a];
  }
  q.normalize();
  s.q[0] = q.w();
  s.q[1] = q.x();
  s.q[2] = q.y();
  s.q[3] = q.z();
  return s;
}

// Body 0 at step k of a rigid motion given in lattice units: centre x (cells), velocity v (cells
// per step), angular velocity w (rad per step) turned since step 0, as the SI state the coupler
// delivers under the unit converter `units`.
inline BodyState moving_state(const Eigen::Vector3d& x, const Eigen::Vector3d& v,
                              const Eigen::Vector3d& w, int k, const UnitConverter& units) {
  const double angle = w.norm() * k;
  const Eigen::Quaterniond q = angle > 0
                                   ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, w.normalized()))
                                   : Eigen::Quaterniond(1, 0, 0, 0);
  return state(0, x * units.dx, q, v * units.velocity(), w / units.dt);
}

// Post-stream populations of every local cell (ghosts included), population-major.
struct Populations {
  CellIndex cells = 0;
  std::vector<double> f;
  explicit Populations(const LocalBox& box)
      : cells(box.cells_with_ghosts()), f(static_cast<std::size_t>(cells) * d3q19::Q, 0.0) {}
  double& at(int i, CellIndex c) { return f[static_cast<std::size_t>(i * cells + c)]; }
  double operator()(int i, CellIndex c) const { return f[static_cast<std::size_t>(i * cells + c)]; }
  // f_i = f_i^eq(rho, u(position)) everywhere.
  template <class U>
  void equilibrium(const Subdomain& sub, double rho, const U& u) {
    const LocalBox& b = sub.box;
    for (int z = 0; z <= b.n[2] + 1; ++z)
      for (int y = 0; y <= b.n[1] + 1; ++y)
        for (int x = 0; x <= b.n[0] + 1; ++x) {
          const Eigen::Vector3d p(sub.position(0, x), sub.position(1, y), sub.position(2, z));
          const Eigen::Vector3d v = u(p);
          for (int i = 0; i < d3q19::Q; ++i)
            at(i, b.index(x, y, z)) = d3q19::equilibrium<double>(i, rho, v[0], v[1], v[2]);
        }
  }
};

}  // namespace lbdem::hlbm::test
