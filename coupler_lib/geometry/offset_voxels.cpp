#include "coupler_lib/geometry/offset_voxels.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/ray_parity.hpp"
#include "coupler_lib/geometry/triangle_band.hpp"
#include "coupler_lib/geometry/voxel_fill.hpp"
#include "coupler_lib/geometry/voxelize.hpp"

namespace lbdem {

namespace {

using Intervals = std::vector<std::pair<double, double>>;  // sorted, disjoint

// Sorted by start, overlapping ones joined.
Intervals merged(Intervals in) {
  std::sort(in.begin(), in.end());
  Intervals out;
  for (const auto& iv : in) {
    if (!out.empty() && iv.first <= out.back().second)
      out.back().second = std::max(out.back().second, iv.second);
    else
      out.push_back(iv);
  }
  return out;
}

// `keep` minus `cut`, both sorted and disjoint.
Intervals minus(const Intervals& keep, const Intervals& cut) {
  Intervals out;
  std::size_t c = 0;
  for (const auto& [a, b] : keep) {
    double from = a;
    while (c < cut.size() && cut[c].second <= from) ++c;
    for (std::size_t q = c; q < cut.size() && cut[q].first < b; ++q) {
      if (cut[q].first > from) out.emplace_back(from, cut[q].first);
      from = std::max(from, cut[q].second);
    }
    if (from < b) out.emplace_back(from, b);
  }
  return out;
}

// The parallel body's part of the vertical line through (x, y), from the triangles that can
// reach it (`near`).
Intervals line_intervals(const TriangleMesh& m, const std::vector<int>& near, double offset,
                         double x, double y) {
  std::vector<double> zs;
  Intervals bands;
  const double r = std::abs(offset);
  for (int t : near) {
    const auto& tri = m.triangles[static_cast<std::size_t>(t)];
    const auto& a = m.vertices[tri[0]];
    const auto& b = m.vertices[tri[1]];
    const auto& c = m.vertices[tri[2]];
    double z, z0, z1;
    if (pierces_column(tri, a, b, c, x, y, z)) zs.push_back(z);
    if (near_triangle_interval(a, b, c, r, x, y, z0, z1)) bands.emplace_back(z0, z1);
  }
  if (zs.size() % 2 != 0) {
    std::ostringstream s;
    s << "offset voxelization: the vertical line x = " << x << ", y = " << y
      << " crosses the surface " << zs.size() << " times (odd); the mesh is not closed";
    throw ShapeError(s.str());
  }
  std::sort(zs.begin(), zs.end());
  Intervals inside;
  for (std::size_t p = 0; p + 1 < zs.size(); p += 2) inside.emplace_back(zs[p], zs[p + 1]);
  if (offset > 0) return minus(inside, merged(std::move(bands)));
  bands.insert(bands.end(), inside.begin(), inside.end());
  return merged(std::move(bands));
}

Voxels offset_mesh(const TriangleMesh& m, double offset, Voxels v) {
  const double h = v.h, r = std::abs(offset);
  const int n0 = v.n[0], n1 = v.n[1], n2 = v.n[2];
  const Eigen::Vector3d lo = v.origin - Eigen::Vector3d::Constant(0.5 * h);  // lattice corner
  // Triangles by the voxel columns their xy bounds, widened by r, overlap.
  std::vector<std::vector<int>> near(static_cast<std::size_t>(n0) * n1);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    Eigen::Vector3d t0 = m.vertices[m.triangles[t][0]], t1 = t0;
    for (int q = 1; q < 3; ++q) {
      t0 = t0.cwiseMin(m.vertices[m.triangles[t][q]]);
      t1 = t1.cwiseMax(m.vertices[m.triangles[t][q]]);
    }
    const int i0 = std::max(0, static_cast<int>(std::floor((t0.x() - r - lo.x()) / h)));
    const int i1 = std::min(n0 - 1, static_cast<int>(std::floor((t1.x() + r - lo.x()) / h)));
    const int j0 = std::max(0, static_cast<int>(std::floor((t0.y() - r - lo.y()) / h)));
    const int j1 = std::min(n1 - 1, static_cast<int>(std::floor((t1.y() + r - lo.y()) / h)));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        near[static_cast<std::size_t>(i) + static_cast<std::size_t>(n0) * j].push_back(
            static_cast<int>(t));
  }
  std::vector<double> fill(v.solid.size(), 0.0);
  const double weight = 1.0 / (kFillSamplesPerAxis * kFillSamplesPerAxis * h);
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      const auto& tris = near[static_cast<std::size_t>(i) + static_cast<std::size_t>(n0) * j];
      if (tris.empty()) continue;  // no surface within reach: the line is outside
      // Solid flags at the voxel centres, with the voxelization's convention (a centre is in
      // when an odd number of boundaries lie strictly below it).
      const Eigen::Vector3d pc = v.center(i, j, 0);
      const Intervals centre = line_intervals(m, tris, offset, pc.x(), pc.y());
      for (const auto& [a, b] : centre)
        for (int k = 0; k < n2; ++k) {
          const double zc = v.origin.z() + h * k;
          if (a < zc && zc <= b) v.solid[v.index(i, j, k)] = 1;
        }
      // Fractions: each sub-column's intervals cut exactly by the voxel layers.
      for (int w = 0; w < kFillSamplesPerAxis; ++w)
        for (int u = 0; u < kFillSamplesPerAxis; ++u) {
          const Eigen::Vector2d o = subcolumn_offset(u, w);
          const double x = lo.x() + (i + o.x()) * h, y = lo.y() + (j + o.y()) * h;
          for (const auto& [a, b] : line_intervals(m, tris, offset, x, y)) {
            const int k0 = std::max(0, static_cast<int>(std::floor((a - lo.z()) / h)));
            const int k1 = std::min(n2 - 1, static_cast<int>(std::floor((b - lo.z()) / h)));
            for (int k = k0; k <= k1; ++k) {
              const double z0 = lo.z() + k * h;
              fill[v.index(i, j, k)] +=
                  std::max(0.0, std::min(b, z0 + h) - std::max(a, z0)) * weight;
            }
          }
        }
    }
  v.fill.resize(fill.size());
  for (std::size_t id = 0; id < fill.size(); ++id) v.fill[id] = snapped_fraction(fill[id]);
  return v;
}

Voxels offset_analytic(const SolidGeometry& s, double offset, Voxels v) {
  // The exact distance only where its cheap bounds (distance_bounds) do not settle the
  // comparison, with a margin of 1e-9 |offset| beyond their round-off: the same decisions as the
  // exact distance everywhere, at a fraction of the cost (the ellipsoid's distance is a root).
  const double margin = 1e-9 * std::abs(offset);
  const auto inside = [&](const Eigen::Vector3d& x) {
    const bool in = s.inside(x);
    if (offset > 0) {
      if (!in) return false;
      const auto [lo, hi] = s.distance_bounds(x);
      if (lo > offset + margin) return true;
      if (hi < offset - margin) return false;
      return s.distance_to_surface(x) >= offset;
    }
    if (in) return true;
    const auto [lo, hi] = s.distance_bounds(x);
    if (hi < -offset - margin) return true;
    if (lo > -offset + margin) return false;
    return s.distance_to_surface(x) <= -offset;
  };
  // |signed distance - offset|, compared by fill_sampled with half a voxel diagonal: where the
  // bounds put the signed distance's whole interval that far from the offset, its gap is
  // returned (a lower bound, so the same decision), else the exact value. Kinds whose bounds
  // are the exact distance (lo = hi) return it at once: their gap is that value.
  const double near = 0.5 * std::sqrt(3.0) * v.h;
  const auto bound = [&](const Eigen::Vector3d& x) {
    const bool in = s.inside(x);
    const auto [lo, hi] = s.distance_bounds(x);
    const double a = in ? lo : -hi, b = in ? hi : -lo;  // the signed distance's interval
    const double gap = offset < a ? a - offset : offset > b ? offset - b : 0.0;
    if (lo == hi || gap > near + margin) return gap;
    const double d = s.distance_to_surface(x);
    return std::abs((in ? d : -d) - offset);
  };
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i)
        v.solid[v.index(i, j, k)] = inside(v.center(i, j, k)) ? 1 : 0;
  fill_sampled(inside, bound, v);
  return v;
}

}  // namespace

Voxels voxelize_offset(const SolidGeometry& solid, double offset, double h, int pad) {
  const Eigen::Vector3d lo = solid.lower() + Eigen::Vector3d::Constant(offset),
                        hi = solid.upper() - Eigen::Vector3d::Constant(offset);
  if (!((hi - lo).minCoeff() > 0)) {
    std::ostringstream s;
    s << "moving the surface of the " << solid.describe() << " inward by " << offset
      << " m leaves no solid";
    throw ShapeError(s.str());
  }
  Voxels v = empty_lattice(lo, hi, h, pad);
  if (solid.kind() == SolidGeometry::Kind::mesh) return offset_mesh(solid.triangles(), offset, v);
  return offset_analytic(solid, offset, v);
}

}  // namespace lbdem
