#include "coupler_lib/geometry/voxel_fill.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/ray_parity.hpp"

namespace lbdem {

namespace {

constexpr int kSub = kFillSamplesPerAxis;

// Length of [a0, a1] inside [b0, b1].
double overlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

void fill_cuboid(const Eigen::Vector3d& edges, Voxels& v) {
  const double h = v.h;
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const Eigen::Vector3d c = v.center(i, j, k);
        double f = 1;
        for (int d = 0; d < 3; ++d)
          f *= overlap(c[d] - 0.5 * h, c[d] + 0.5 * h, -0.5 * edges[d], 0.5 * edges[d]) / h;
        v.fill[v.index(i, j, k)] = snapped_fraction(f);
      }
}

}  // namespace

float snapped_fraction(double f) {
  constexpr double kSnap = 1e-5;
  if (f < kSnap) return 0.0f;
  if (f > 1 - kSnap) return 1.0f;
  return static_cast<float>(f);
}

void fill_sampled(const PointTest& inside, const DistanceBound& surface_distance_bound, Voxels& v) {
  v.fill.assign(v.solid.size(), 0.0f);
  const double h = v.h, near = 0.5 * std::sqrt(3.0) * h;
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const std::size_t id = v.index(i, j, k);
        const Eigen::Vector3d c = v.center(i, j, k);
        if (surface_distance_bound(c) > near) {
          v.fill[id] = v.solid[id];
          continue;
        }
        int in = 0;
        for (int c2 = 0; c2 < kSub; ++c2)
          for (int c1 = 0; c1 < kSub; ++c1)
            for (int c0 = 0; c0 < kSub; ++c0) {
              const Eigen::Vector3d off = (Eigen::Vector3d(c0, c1, c2).array() + 0.5) / kSub - 0.5;
              in += inside(c + h * off) ? 1 : 0;
            }
        v.fill[id] = static_cast<float>(in) / (kSub * kSub * kSub);
      }
}

void fill_fractions(const TriangleMesh& mesh, Voxels& v) {
  const double h = v.h, sub = h / kSub;
  const int n0 = v.n[0], n1 = v.n[1], n2 = v.n[2];
  const Eigen::Vector3d lo = v.origin - Eigen::Vector3d::Constant(0.5 * h);  // lattice corner
  std::vector<double> fill(v.solid.size(), 0.0);
  // Triangles by the voxel rows (j) their y extent touches, so one row of sub-columns is
  // held at a time.
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(n1));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const double y0 =
        std::min({mesh.vertices[tri[0]].y(), mesh.vertices[tri[1]].y(), mesh.vertices[tri[2]].y()});
    const double y1 =
        std::max({mesh.vertices[tri[0]].y(), mesh.vertices[tri[1]].y(), mesh.vertices[tri[2]].y()});
    const int j0 = std::max(0, static_cast<int>(std::floor((y0 - lo.y()) / h)));
    const int j1 = std::min(n1 - 1, static_cast<int>(std::floor((y1 - lo.y()) / h)));
    for (int j = j0; j <= j1; ++j) rows[static_cast<std::size_t>(j)].push_back(static_cast<int>(t));
  }
  const int m0 = n0 * kSub;  // sub-columns along x
  std::vector<std::vector<double>> crossings(static_cast<std::size_t>(m0) * kSub);
  const double weight = 1.0 / (kSub * kSub * h);
  for (int j = 0; j < n1; ++j) {
    for (auto& zs : crossings) zs.clear();
    for (int t : rows[static_cast<std::size_t>(j)]) {
      const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
      const auto& a = mesh.vertices[tri[0]];
      const auto& b = mesh.vertices[tri[1]];
      const auto& c = mesh.vertices[tri[2]];
      const double x0 = std::min({a.x(), b.x(), c.x()}), x1 = std::max({a.x(), b.x(), c.x()});
      const double y0 = std::min({a.y(), b.y(), c.y()}), y1 = std::max({a.y(), b.y(), c.y()});
      // Sub-column u samples x within [u, u + 1) sub widths from the corner.
      const int u0 = std::max(0, static_cast<int>(std::floor((x0 - lo.x()) / sub)) - 1);
      const int u1 = std::min(m0 - 1, static_cast<int>(std::floor((x1 - lo.x()) / sub)) + 1);
      for (int w = 0; w < kSub; ++w) {
        for (int u = u0; u <= u1; ++u) {
          const Eigen::Vector2d o = subcolumn_offset(u % kSub, w);
          const double x = lo.x() + (u / kSub + o.x()) * h, y = lo.y() + (j + o.y()) * h;
          if (y < y0 || y > y1) continue;
          double z;
          if (pierces_column(tri, a, b, c, x, y, z))
            crossings[static_cast<std::size_t>(u) + static_cast<std::size_t>(m0) * w].push_back(z);
        }
      }
    }
    for (int w = 0; w < kSub; ++w)
      for (int u = 0; u < m0; ++u) {
        auto& zs = crossings[static_cast<std::size_t>(u) + static_cast<std::size_t>(m0) * w];
        if (zs.empty()) continue;
        if (zs.size() % 2 != 0) {
          std::ostringstream s;
          const Eigen::Vector2d o = subcolumn_offset(u % kSub, w);
          s << "voxel fill: the vertical line x = " << lo.x() + (u / kSub + o.x()) * h
            << ", y = " << lo.y() + (j + o.y()) * h << " crosses the surface " << zs.size()
            << " times (odd); the mesh is not closed";
          throw ShapeError(s.str());
        }
        std::sort(zs.begin(), zs.end());
        const int i = u / kSub;
        // Inside intervals [zs[0], zs[1]], [zs[2], zs[3]], ... cut exactly by the voxel layers.
        for (std::size_t p = 0; p + 1 < zs.size(); p += 2) {
          const int k0 = std::max(0, static_cast<int>(std::floor((zs[p] - lo.z()) / h)));
          const int k1 = std::min(n2 - 1, static_cast<int>(std::floor((zs[p + 1] - lo.z()) / h)));
          for (int k = k0; k <= k1; ++k) {
            const double z0 = lo.z() + k * h;
            fill[v.index(i, j, k)] += overlap(zs[p], zs[p + 1], z0, z0 + h) * weight;
          }
        }
      }
  }
  v.fill.resize(fill.size());
  for (std::size_t id = 0; id < fill.size(); ++id) v.fill[id] = snapped_fraction(fill[id]);
}

void fill_fractions(const SolidGeometry& solid, Voxels& v) {
  v.fill.assign(v.solid.size(), 0.0f);
  switch (solid.kind()) {
    case SolidGeometry::Kind::cuboid:
      fill_cuboid(solid.parameters(), v);
      return;
    case SolidGeometry::Kind::sphere:
    case SolidGeometry::Kind::ellipsoid:
      fill_sampled([&](const Eigen::Vector3d& x) { return solid.inside(x); },
                   [&](const Eigen::Vector3d& x) { return solid.distance_to_surface(x); }, v);
      return;
    case SolidGeometry::Kind::mesh:
      fill_fractions(solid.triangles(), v);
      return;
  }
}

}  // namespace lbdem
