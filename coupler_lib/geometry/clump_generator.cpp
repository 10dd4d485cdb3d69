#include "coupler_lib/geometry/clump_generator.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/distance_transform.hpp"
#include "coupler_lib/geometry/mass_properties.hpp"

namespace lbdem {

namespace {

// Marks every voxel whose centre lies in the sphere (c, r); returns how many were new.
std::size_t mark_sphere(const Voxels& lattice, const Eigen::Vector3d& c, double r,
                        std::vector<std::uint8_t>& mark) {
  std::array<int, 3> lo{}, hi{};
  for (int d = 0; d < 3; ++d) {
    // Clamp in floating point first: a sphere far off the lattice must not overflow int.
    const double top = lattice.n[d] - 1;
    lo[d] = static_cast<int>(
        std::clamp(std::ceil((c[d] - r - lattice.origin[d]) / lattice.h), 0.0, top + 1));
    hi[d] = static_cast<int>(
        std::clamp(std::floor((c[d] + r - lattice.origin[d]) / lattice.h), -1.0, top));
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

// Depth of an inside point as a sphere radius; a non-finite value would mark the whole
// lattice, so it is an error rather than a silent bad clump.
double checked_radius(const SolidGeometry& solid, const Eigen::Vector3d& c) {
  const double r = solid.distance_to_surface(c);
  if (!std::isfinite(r) || r < 0) {
    std::ostringstream s;
    s << "distance from (" << c.transpose() << ") to the surface of " << solid.describe() << " is "
      << r;
    throw ShapeError(s.str());
  }
  return r;
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
  clump.radii.push_back(checked_radius(solid, c));
}

// Depth of x below the surface (negative outside).
double depth(const SolidGeometry& solid, const Eigen::Vector3d& x) {
  const double d = solid.distance_to_surface(x);
  return solid.inside(x) ? d : -d;
}

// Moves a voxel centre within its cell to where the inscribed sphere is largest (compass
// search on the exact depth): a lattice with an even count across a symmetric shape has no
// voxel at the centre, and the first sphere would otherwise be short by up to sqrt(3) h/2.
Eigen::Vector3d deepest_in_cell(const SolidGeometry& solid, const Eigen::Vector3d& c0, double h) {
  Eigen::Vector3d p = c0;
  double best = depth(solid, p);
  for (double step = 0.5 * h; step > 1e-4 * h;) {
    bool moved = false;
    for (int d = 0; d < 3 && !moved; ++d)
      for (double sign : {-1.0, 1.0}) {
        Eigen::Vector3d q = p;
        q[d] += sign * step;
        if (std::abs(q[d] - c0[d]) > 0.5 * h) continue;
        const double dq = depth(solid, q);
        if (dq > best) {
          best = dq;
          p = q;
          moved = true;
          break;
        }
      }
    if (!moved) step *= 0.5;
  }
  return p;
}

// Voxels not reachable from the lattice boundary through empty voxels (6-connected flood
// fill) become solid: a cavity enclosed by the spheres cannot be reached by another body,
// so it is not a shape error that contacts can see.
void fill_cavities(Voxels& v) {
  std::vector<std::uint8_t> outside(v.solid.size(), 0);
  std::vector<std::array<int, 3>> stack;
  auto push = [&](int i, int j, int k) {
    if (i < 0 || j < 0 || k < 0 || i >= v.n[0] || j >= v.n[1] || k >= v.n[2]) return;
    const auto id = v.index(i, j, k);
    if (v.solid[id] || outside[id]) return;
    outside[id] = 1;
    stack.push_back({i, j, k});
  };
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i)
        if (i == 0 || j == 0 || k == 0 || i == v.n[0] - 1 || j == v.n[1] - 1 || k == v.n[2] - 1)
          push(i, j, k);
  while (!stack.empty()) {
    const auto [i, j, k] = stack.back();
    stack.pop_back();
    push(i - 1, j, k);
    push(i + 1, j, k);
    push(i, j - 1, k);
    push(i, j + 1, k);
    push(i, j, k - 1);
    push(i, j, k + 1);
  }
  for (std::size_t id = 0; id < v.solid.size(); ++id) v.solid[id] = !outside[id];
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
    const Eigen::Vector3d c = deepest_in_cell(solid, voxels.center(i, j, k), voxels.h);
    // The exact depth of the centre: the largest sphere there that stays inside.
    const double r = checked_radius(solid, c);
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
  Voxels cv = clump_voxels(clump, voxels);
  fill_cavities(cv);
  // Two-sided (Hausdorff) deviation: a voxel of the shape the clump misses is as far off as
  // the nearest clump voxel, a clump voxel outside the shape as far as the nearest shape
  // voxel; centre-to-centre distances less h/2 approximate the surface-to-point distance.
  const auto to_shape = distance_to_solid(voxels);
  const auto to_clump = distance_to_solid(cv);
  std::size_t mismatch = 0, solid = 0;
  for (std::size_t i = 0; i < voxels.solid.size(); ++i) {
    solid += voxels.solid[i];
    if (cv.solid[i] == voxels.solid[i]) continue;
    ++mismatch;
    const double d = voxels.solid[i] ? to_clump[i] : to_shape[i];
    q.max_deviation = std::max(q.max_deviation, d - 0.5 * voxels.h);
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
