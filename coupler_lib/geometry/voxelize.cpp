#include "coupler_lib/geometry/voxelize.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/ray_parity.hpp"
#include "coupler_lib/geometry/voxel_fill.hpp"

namespace lbdem {

// A tolerance of 1e-9 keeps an extent that is a multiple of h from gaining a layer by
// round-off.
Voxels empty_lattice(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double h, int pad) {
  if (!(h > 0)) throw ShapeError("voxel spacing must be positive, got " + std::to_string(h));
  Voxels v;
  v.h = h;
  const Eigen::Vector3d c = 0.5 * (lo + hi);
  double total = 1;
  std::array<double, 3> across{};
  for (int d = 0; d < 3; ++d) {
    across[d] = std::max(1.0, std::ceil((hi[d] - lo[d]) / h - 1e-9)) + 2 * pad;
    total *= across[d];
  }
  if (total > 2e9) {
    std::ostringstream s;
    s << "voxel spacing " << h << " gives " << across[0] << " x " << across[1] << " x " << across[2]
      << " voxels, too many; use a larger spacing";
    throw ShapeError(s.str());
  }
  for (int d = 0; d < 3; ++d) {
    v.n[d] = static_cast<int>(across[d]);
    v.origin[d] = c[d] - 0.5 * (v.n[d] - 1) * h;
  }
  v.solid.assign(static_cast<std::size_t>(total), 0);
  return v;
}

Voxels voxelize_mesh(const TriangleMesh& mesh, double h, int pad) {
  Eigen::Vector3d lo, hi;
  bounding_box(mesh, lo, hi);
  Voxels v = empty_lattice(lo, hi, h, pad);
  const int n0 = v.n[0], n1 = v.n[1], n2 = v.n[2];
  // Crossing heights per column of voxel centres; each triangle visits only the columns
  // under its xy bounding box, so the cost scales with the surface, not the volume.
  std::vector<std::vector<double>> columns(static_cast<std::size_t>(n0) * n1);
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    const auto& b = mesh.vertices[t[1]];
    const auto& c = mesh.vertices[t[2]];
    const double x0 = std::min({a.x(), b.x(), c.x()}), x1 = std::max({a.x(), b.x(), c.x()});
    const double y0 = std::min({a.y(), b.y(), c.y()}), y1 = std::max({a.y(), b.y(), c.y()});
    const int i0 = std::max(0, static_cast<int>(std::ceil((x0 - v.origin.x()) / h)) - 1);
    const int i1 = std::min(n0 - 1, static_cast<int>(std::floor((x1 - v.origin.x()) / h)) + 1);
    const int j0 = std::max(0, static_cast<int>(std::ceil((y0 - v.origin.y()) / h)) - 1);
    const int j1 = std::min(n1 - 1, static_cast<int>(std::floor((y1 - v.origin.y()) / h)) + 1);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const Eigen::Vector3d p = v.center(i, j, 0);
        double z;
        if (pierces_column(t, a, b, c, p.x(), p.y(), z))
          columns[static_cast<std::size_t>(i) + static_cast<std::size_t>(n0) * j].push_back(z);
      }
    }
  }
  for (int j = 0; j < n1; ++j) {
    for (int i = 0; i < n0; ++i) {
      auto& zs = columns[static_cast<std::size_t>(i) + static_cast<std::size_t>(n0) * j];
      if (zs.empty()) continue;
      if (zs.size() % 2 != 0) {
        const Eigen::Vector3d p = v.center(i, j, 0);
        std::ostringstream s;
        s << "voxelization: the vertical line x = " << p.x() << ", y = " << p.y() << " crosses the "
          << "surface " << zs.size() << " times (odd); the mesh is not closed";
        throw ShapeError(s.str());
      }
      std::sort(zs.begin(), zs.end());
      std::size_t below = 0;
      for (int k = 0; k < n2; ++k) {
        const double zc = v.origin.z() + h * k;
        while (below < zs.size() && zs[below] < zc) ++below;
        v.solid[v.index(i, j, k)] = below % 2;
      }
    }
  }
  fill_fractions(mesh, v);
  return v;
}

Voxels voxelize(const SolidGeometry& geometry, double h, int pad) {
  if (geometry.kind() == SolidGeometry::Kind::mesh)
    return voxelize_mesh(geometry.triangles(), h, pad);
  Voxels v = empty_lattice(geometry.lower(), geometry.upper(), h, pad);
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i)
        v.solid[v.index(i, j, k)] = geometry.inside(v.center(i, j, k)) ? 1 : 0;
  fill_fractions(geometry, v);
  return v;
}

Voxels box_averaged(Voxels v) {
  // One axis at a time (the cube's volume fractions are products of the per-axis ones), each
  // pass summed in double from the previous pass's values.
  std::vector<double> a(v.fill.begin(), v.fill.end()), b(a.size());
  const std::array<std::size_t, 3> stride = {1, static_cast<std::size_t>(v.n[0]),
                                             static_cast<std::size_t>(v.n[0]) * v.n[1]};
  for (int axis = 0; axis < 3; ++axis) {
    const std::size_t s = stride[static_cast<std::size_t>(axis)];
    for (int k = 0; k < v.n[2]; ++k)
      for (int j = 0; j < v.n[1]; ++j)
        for (int i = 0; i < v.n[0]; ++i) {
          const std::size_t idx = v.index(i, j, k);
          const int l = axis == 0 ? i : axis == 1 ? j : k;
          const double below = l > 0 ? a[idx - s] : 0.0;
          const double above = l + 1 < v.n[static_cast<std::size_t>(axis)] ? a[idx + s] : 0.0;
          b[idx] = 0.25 * below + 0.5 * a[idx] + 0.25 * above;
        }
    std::swap(a, b);
  }
  for (std::size_t idx = 0; idx < a.size(); ++idx) v.fill[idx] = static_cast<float>(a[idx]);
  return v;
}

Voxels translated(Voxels v, const Eigen::Vector3d& shift) {
  v.origin -= shift;
  return v;
}

}  // namespace lbdem
