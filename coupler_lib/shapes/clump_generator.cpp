#include "coupler_lib/shapes/clump_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "coupler_lib/shapes/distance_transform.hpp"
#include "coupler_lib/shapes/mass_properties.hpp"
#include "coupler_lib/shapes/shape_error.hpp"

namespace lbdem {

namespace {

// Marks every voxel whose centre lies in the sphere (c, r); returns how many were new.
std::size_t mark_sphere(const Voxels& lattice, const Eigen::Vector3d& c, double r,
                        std::vector<std::uint8_t>& mark) {
  std::array<int, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    lo[d] = std::max(0, static_cast<int>(std::ceil((c[d] - r - lattice.origin[d]) / lattice.h)));
    hi[d] = std::min(lattice.n[d] - 1,
                     static_cast<int>(std::floor((c[d] + r - lattice.origin[d]) / lattice.h)));
  }
  std::size_t fresh = 0;
  const double r2 = r * r;
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        if ((lattice.center(i, j, k) - c).squaredNorm() > r2) continue;
        auto& m = mark[lattice.index(i, j, k)];
        fresh += m == 0;
        m = 1;
      }
  return fresh;
}

// The sphere added at the centre: at the voxel centroid with its exact depth as radius, or
// at the deepest voxel when the centroid lies outside a non-convex solid.
void add_center_sphere(const SolidGeometry& solid, const Voxels& voxels, Clump& clump) {
  Eigen::Vector3d c = mass_properties(voxels).centroid;
  if (!solid.inside(c)) {
    const auto dist = distance_to_other_kind(voxels);
    std::size_t best = 0;
    for (std::size_t i = 0; i < dist.size(); ++i)
      if (voxels.solid[i] && (!voxels.solid[best] || dist[i] > dist[best])) best = i;
    const int i0 = static_cast<int>(best % voxels.n[0]);
    const int j0 = static_cast<int>((best / voxels.n[0]) % voxels.n[1]);
    const int k0 = static_cast<int>(best / (std::size_t(voxels.n[0]) * voxels.n[1]));
    c = voxels.center(i0, j0, k0);
  }
  clump.centers.push_back(c);
  clump.radii.push_back(solid.distance_to_surface(c));
}

}  // namespace

Clump surface_clump(const SolidGeometry& solid, const Voxels& voxels,
                    const SurfaceClumpOptions& opt) {
  if (opt.grid < 2) throw ShapeError("surface clump: grid must be at least 2");
  if (!(opt.radius_ratio > 0)) throw ShapeError("surface clump: radius_ratio must be positive");
  const Eigen::Vector3d lo = solid.lower(), hi = solid.upper();
  const Eigen::Vector3d mid = 0.5 * (lo + hi);
  const double L = (hi - lo).maxCoeff();
  // n points span the eroded edge L - 2r with r = ratio * s: s (n - 1) = L - 2 ratio s.
  const double s = L / (opt.grid - 1 + 2 * opt.radius_ratio);
  const double r = opt.radius_ratio * s;
  std::array<int, 3> n{};
  for (int d = 0; d < 3; ++d)
    n[d] = std::max(1, static_cast<int>(std::floor((hi[d] - lo[d] - 2 * r) / s + 1e-9)) + 1);
  auto point = [&](int i, int j, int k) {
    return Eigen::Vector3d(mid.x() + s * (i - 0.5 * (n[0] - 1)),
                           mid.y() + s * (j - 0.5 * (n[1] - 1)),
                           mid.z() + s * (k - 0.5 * (n[2] - 1)));
  };
  // A grid point can carry a sphere when the sphere fits inside: depth >= r (relative
  // round-off allowance, so points exactly on a flat eroded face count).
  const double tol = 1e-9 * L;
  std::vector<std::uint8_t> fits(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0);
  auto at = [&](int i, int j, int k) {
    return i + std::size_t(n[0]) * (j + std::size_t(n[1]) * k);
  };
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const Eigen::Vector3d p = point(i, j, k);
        fits[at(i, j, k)] = solid.inside(p) && solid.distance_to_surface(p) >= r - tol;
      }
  // Keep the boundary of the fitting set: points with a face neighbour that does not fit
  // (or lies off the grid).
  Clump clump;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        if (!fits[at(i, j, k)]) continue;
        const int nb[6][3] = {{i - 1, j, k}, {i + 1, j, k}, {i, j - 1, k},
                              {i, j + 1, k}, {i, j, k - 1}, {i, j, k + 1}};
        bool boundary = false;
        for (const auto& q : nb) {
          if (q[0] < 0 || q[1] < 0 || q[2] < 0 || q[0] >= n[0] || q[1] >= n[1] || q[2] >= n[2] ||
              !fits[at(q[0], q[1], q[2])]) {
            boundary = true;
            break;
          }
        }
        if (!boundary) continue;
        clump.centers.push_back(point(i, j, k));
        clump.radii.push_back(r);
      }
  if (clump.radii.empty())
    throw ShapeError("surface clump: no grid point of spacing " + std::to_string(s) +
                     " fits a sphere of radius " + std::to_string(r) + " inside " +
                     solid.describe() + "; use a larger grid");
  if (opt.center_sphere) add_center_sphere(solid, voxels, clump);
  return clump;
}

Clump fill_clump(const SolidGeometry& solid, const Voxels& voxels, const FillClumpOptions& opt) {
  if (opt.spheres < 1) throw ShapeError("fill clump: the sphere count must be at least 1");
  const auto dist = distance_to_other_kind(voxels);
  const Eigen::Vector3d centroid = mass_properties(voxels).centroid;
  // Candidate centres: solid voxels, deepest first; ties go to the voxel nearest the
  // centroid, then to the lower index, so the result is deterministic and symmetric shapes
  // start from their centre.
  std::vector<std::size_t> order;
  std::vector<double> off(voxels.solid.size(), 0);
  for (int k = 0; k < voxels.n[2]; ++k)
    for (int j = 0; j < voxels.n[1]; ++j)
      for (int i = 0; i < voxels.n[0]; ++i) {
        const std::size_t id = voxels.index(i, j, k);
        if (!voxels.solid[id]) continue;
        order.push_back(id);
        off[id] = (voxels.center(i, j, k) - centroid).squaredNorm();
      }
  if (order.empty()) throw ShapeError("fill clump: the voxelization has no solid voxel");
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (dist[a] != dist[b]) return dist[a] > dist[b];
    if (off[a] != off[b]) return off[a] < off[b];
    return a < b;
  });
  std::vector<std::uint8_t> covered(voxels.solid.size(), 0);
  Clump clump;
  const std::size_t plane = std::size_t(voxels.n[0]) * voxels.n[1];
  for (std::size_t next = 0; next < order.size() && int(clump.size()) < opt.spheres; ++next) {
    const std::size_t id = order[next];
    if (covered[id]) continue;
    const int i = static_cast<int>(id % voxels.n[0]);
    const int j = static_cast<int>((id / voxels.n[0]) % voxels.n[1]);
    const int k = static_cast<int>(id / plane);
    const Eigen::Vector3d c = voxels.center(i, j, k);
    // The exact depth of the centre: the largest sphere there that stays inside.
    const double r = solid.distance_to_surface(c);
    clump.centers.push_back(c);
    clump.radii.push_back(r);
    mark_sphere(voxels, c, r, covered);
    covered[id] = 1;
  }
  return clump;
}

Voxels clump_voxels(const Clump& clump, const Voxels& lattice) {
  Voxels out = lattice;
  std::fill(out.solid.begin(), out.solid.end(), 0);
  for (std::size_t s = 0; s < clump.size(); ++s)
    mark_sphere(out, clump.centers[s], clump.radii[s], out.solid);
  return out;
}

ClumpQuality clump_quality(const Clump& clump, const Voxels& voxels) {
  ClumpQuality q;
  q.lattice_spacing = voxels.h;
  const Voxels cv = clump_voxels(clump, voxels);
  const auto dist = distance_to_other_kind(voxels);
  std::size_t mismatch = 0, solid = 0;
  for (std::size_t i = 0; i < voxels.solid.size(); ++i) {
    solid += voxels.solid[i];
    if (cv.solid[i] == voxels.solid[i]) continue;
    ++mismatch;
    q.max_deviation = std::max(q.max_deviation, dist[i] - 0.5 * voxels.h);
  }
  q.volume_error = solid ? double(mismatch) / double(solid) : 0.0;
  // A clump reaching beyond the lattice is mismatched outside it too; count what sticks out.
  for (std::size_t s = 0; s < clump.size(); ++s)
    for (int d = 0; d < 3; ++d) {
      const double below = voxels.origin[d] - (clump.centers[s][d] - clump.radii[s]);
      const double above =
          clump.centers[s][d] + clump.radii[s] - (voxels.origin[d] + voxels.h * (voxels.n[d] - 1));
      q.max_deviation = std::max({q.max_deviation, below, above});
    }
  return q;
}

Clump translated(Clump c, const Eigen::Vector3d& shift) {
  for (auto& p : c.centers) p -= shift;
  return c;
}

}  // namespace lbdem
