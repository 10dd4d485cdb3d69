#include "coupler_lib/scene/body_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

double clump_extent(const Shape& shape) {
  double r = 0;
  for (size_t i = 0; i < shape.clump.centers.size(); ++i)
    r = std::max(r, shape.clump.centers[i].norm() + shape.clump.radii[i]);
  return r;
}

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw SceneError(file + ": " + what);
}

std::string body_name(size_t i) {
  return "body " + std::to_string(i);
}

Eigen::Quaterniond quaternion(const std::array<double, 4>& q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

Eigen::Vector3d vector(const std::array<double, 3>& v) {
  return {v[0], v[1], v[2]};
}

// Extent of a rotated clump along each axis, relative to the body centre: [min, max].
std::array<std::array<double, 2>, 3> rotated_extent(const Shape& shape,
                                                    const Eigen::Matrix3d& rot) {
  std::array<std::array<double, 2>, 3> e{};
  for (auto& a : e)
    a = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (size_t k = 0; k < shape.clump.centers.size(); ++k) {
    const Eigen::Vector3d c = rot * shape.clump.centers[k];
    for (int d = 0; d < 3; ++d) {
      e[d][0] = std::min(e[d][0], c[d] - shape.clump.radii[k]);
      e[d][1] = std::max(e[d][1], c[d] + shape.clump.radii[k]);
    }
  }
  return e;
}

}  // namespace

void check_body_placement(const std::string& file, const std::vector<Shape>& shapes,
                          const std::vector<BodyParams>& bodies,
                          const std::array<double, 3>& box_lo, const std::array<double, 3>& box_hi,
                          const DemParams& p) {
  // Walls: not on periodic axes, inside the box.
  for (size_t w = 0; w < p.walls.size(); ++w) {
    const auto& wall = p.walls[w];
    const std::string where = "dem.walls[" + std::to_string(w) + "]: ";
    if (p.periodic[wall.axis])
      fail(file, where + "a wall normal to " + axis_name(wall.axis) + " on a periodic axis");
    const double pos = wall.position.value_or(wall.lower ? box_lo[wall.axis] : box_hi[wall.axis]);
    if (pos < box_lo[wall.axis] || pos > box_hi[wall.axis])
      fail(file, where + "position " + std::to_string(pos) + " lies outside the box");
  }

  // Bodies: known shape, inside the box, clear of walls.
  std::vector<Eigen::Matrix3d> rot(bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) {
    const auto& b = bodies[i];
    if (b.shape < 0 || static_cast<size_t>(b.shape) >= shapes.size())
      fail(file, "bodies: " + body_name(i) + " refers to shape " + std::to_string(b.shape) +
                     " which does not exist");
    if (!(b.density > 0)) fail(file, "bodies: " + body_name(i) + " needs a positive density");
    const Shape& sh = shapes[static_cast<size_t>(b.shape)];
    rot[i] = quaternion(b.orientation).normalized().toRotationMatrix();
    const auto ext = rotated_extent(sh, rot[i]);
    for (int d = 0; d < 3; ++d)
      if (ext[d][1] - ext[d][0] > box_hi[d] - box_lo[d]) {
        std::ostringstream m;
        m << "bodies: " << body_name(i) << " is " << ext[d][1] - ext[d][0] << " m across along "
          << axis_name(d) << ", larger than the box (" << box_hi[d] - box_lo[d] << " m)";
        fail(file, m.str());
      }
    for (int d = 0; d < 3; ++d) {
      const double x = b.position[d];
      const bool inside = p.periodic[d]
                              ? (x >= box_lo[d] && x < box_hi[d])
                              : (x + ext[d][0] >= box_lo[d] && x + ext[d][1] <= box_hi[d]);
      if (!inside) {
        std::ostringstream m;
        m << "bodies: " << body_name(i) << " at (" << b.position[0] << ", " << b.position[1] << ", "
          << b.position[2] << ") " << (p.periodic[d] ? "has its centre" : "reaches")
          << " outside the box along " << axis_name(d) << " [" << box_lo[d] << ", " << box_hi[d]
          << "]";
        fail(file, m.str());
      }
    }
    for (size_t w = 0; w < p.walls.size(); ++w) {
      const auto& wall = p.walls[w];
      const int d = wall.axis;
      const double pos = wall.position.value_or(wall.lower ? box_lo[d] : box_hi[d]);
      const bool clear =
          wall.lower ? b.position[d] + ext[d][0] >= pos : b.position[d] + ext[d][1] <= pos;
      if (!clear)
        fail(file, "bodies: " + body_name(i) + " overlaps dem.walls[" + std::to_string(w) + "] (" +
                       axis_name(d) + " = " + std::to_string(pos) + ")");
    }
  }

  std::vector<BodyPose> poses;
  for (size_t i = 0; i < bodies.size(); ++i)
    poses.push_back({bodies[i].shape, vector(bodies[i].position), rot[i]});
  if (const auto o = deepest_clump_overlap(shapes, poses, box_lo, box_hi, p.periodic))
    fail(file, "bodies: " + body_name(o->a) + " and " + body_name(o->b) + " overlap initially");
}

std::optional<ClumpOverlap> deepest_clump_overlap(const std::vector<Shape>& shapes,
                                                  const std::vector<BodyPose>& bodies,
                                                  const std::array<double, 3>& box_lo,
                                                  const std::array<double, 3>& box_hi,
                                                  const std::array<bool, 3>& periodic) {
  double max_extent = 0;
  for (const BodyPose& b : bodies)
    max_extent = std::max(max_extent, clump_extent(shapes[static_cast<size_t>(b.shape)]));
  // Cell list on centres (cell = two extents), minimum image on periodic axes.
  const double h = std::max(2 * max_extent, std::numeric_limits<double>::min());
  std::array<long, 3> nc{};
  std::array<double, 3> len{};
  for (int d = 0; d < 3; ++d) {
    len[d] = box_hi[d] - box_lo[d];
    nc[d] = std::max(1L, static_cast<long>(len[d] / h));
  }
  auto cell = [&](const Eigen::Vector3d& x, int d) {
    double u = (x[d] - box_lo[d]) / len[d];
    if (periodic[d]) u -= std::floor(u);
    return std::clamp(static_cast<long>(u * double(nc[d])), 0L, nc[d] - 1);
  };
  std::unordered_map<long, std::vector<size_t>> grid;
  auto key = [&](long i, long j, long k) { return i + nc[0] * (j + nc[1] * k); };
  for (size_t i = 0; i < bodies.size(); ++i)
    grid[key(cell(bodies[i].x, 0), cell(bodies[i].x, 1), cell(bodies[i].x, 2))].push_back(i);
  std::optional<ClumpOverlap> worst;
  auto measure = [&](size_t a, size_t b) {
    const BodyPose& A = bodies[a];
    const BodyPose& B = bodies[b];
    const Shape& sa = shapes[static_cast<size_t>(A.shape)];
    const Shape& sb = shapes[static_cast<size_t>(B.shape)];
    Eigen::Vector3d dxy = B.x - A.x;
    for (int d = 0; d < 3; ++d)
      if (periodic[d]) dxy[d] -= len[d] * std::round(dxy[d] / len[d]);
    if (dxy.norm() >= clump_extent(sa) + clump_extent(sb)) return;
    for (size_t u = 0; u < sa.clump.centers.size(); ++u)
      for (size_t v = 0; v < sb.clump.centers.size(); ++v) {
        const Eigen::Vector3d ca = A.rot * sa.clump.centers[u];
        const Eigen::Vector3d cb = dxy + B.rot * sb.clump.centers[v];
        const double depth = sa.clump.radii[u] + sb.clump.radii[v] - (cb - ca).norm();
        if (depth <= 0) continue;
        const double fraction = depth / std::min(sa.clump.radii[u], sb.clump.radii[v]);
        if (!worst || fraction > worst->fraction)
          worst = ClumpOverlap{a, b, depth, fraction, A.x + ca + 0.5 * (cb - ca)};
      }
  };
  std::vector<std::pair<size_t, size_t>> seen;
  for (size_t i = 0; i < bodies.size(); ++i) {
    const long ci = cell(bodies[i].x, 0), cj = cell(bodies[i].x, 1), ck = cell(bodies[i].x, 2);
    seen.clear();
    for (long dk = -1; dk <= 1; ++dk)
      for (long dj = -1; dj <= 1; ++dj)
        for (long di = -1; di <= 1; ++di) {
          std::array<long, 3> c{ci + di, cj + dj, ck + dk};
          bool skip = false;
          for (int d = 0; d < 3; ++d) {
            if (c[d] < 0 || c[d] >= nc[d]) {
              if (!periodic[d]) skip = true;
              c[d] = (c[d] + nc[d]) % nc[d];
            }
          }
          if (skip) continue;
          auto it = grid.find(key(c[0], c[1], c[2]));
          if (it == grid.end()) continue;
          for (size_t j : it->second) {
            // With fewer than three cells on an axis, two neighbour cells are the same cell.
            if (j <= i || std::find(seen.begin(), seen.end(), std::pair{i, j}) != seen.end())
              continue;
            seen.emplace_back(i, j);
            measure(i, j);
          }
        }
  }
  return worst;
}

}  // namespace lbdem
