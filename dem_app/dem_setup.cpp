#include "dem_app/dem_setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <unordered_map>

#include "dem_app/contact_model.hpp"
#include "dem_app/lubrication_setup.hpp"
#include "dem_app/quaternion.hpp"

namespace lbdem {

double smallest_sphere_radius(const Shape& shape) {
  return *std::min_element(shape.clump.radii.begin(), shape.clump.radii.end());
}

double clump_extent(const Shape& shape) {
  double r = 0;
  for (size_t i = 0; i < shape.clump.centers.size(); ++i)
    r = std::max(r, shape.clump.centers[i].norm() + shape.clump.radii[i]);
  return r;
}

DemSetup make_dem_setup(const Scene& scene, std::vector<Shape> shapes, bool coupled) {
  if (!scene.dem) throw SceneError(scene.file + ": the scene has no 'dem' section");
  DemSetup s;
  s.file = scene.file;
  s.params = *scene.dem;
  s.shapes = std::move(shapes);
  s.bodies = scene.bodies;
  if (s.params.has_box) {
    s.box_lo = s.params.box_lo;
    s.box_hi = s.params.box_hi;
  } else if (scene.fluid) {
    s.box_lo = {0, 0, 0};
    s.box_hi = scene.fluid->domain;
  } else {
    throw SceneError(scene.file + ": dem.box: required when the scene has no fluid section");
  }
  if (coupled && s.params.buoyancy_fluid_density > 0)
    throw SceneError(scene.file +
                     ": dem.buoyancy_fluid_density: only for DEM-only scenes; in a coupled run "
                     "the fluid side supplies buoyancy");
  // The lubrication correction adds its forces through the same fix external.
  s.external_loads = coupled || s.params.buoyancy_fluid_density > 0 || s.params.lubrication.enabled;
  return s;
}

namespace {

[[noreturn]] void fail(const DemSetup& s, const std::string& what) {
  throw SceneError(s.file + ": " + what);
}

std::string body_name(size_t i) {
  return "body " + std::to_string(i);
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

void validate_dem_setup(const DemSetup& s) {
  const auto& p = s.params;
  if (s.shapes.empty()) fail(s, "shapes: the scene defines no shapes, but DEM needs at least one");
  if (s.bodies.empty()) fail(s, "bodies: the scene has a dem section but no bodies");
  for (size_t i = 0; i < s.shapes.size(); ++i) {
    const auto& sh = s.shapes[i];
    const std::string where = "shapes[" + std::to_string(i) + "] '" + sh.name + "': ";
    if (sh.clump.centers.empty() || sh.clump.centers.size() != sh.clump.radii.size())
      fail(s, where + "the clump has no spheres (or radii and centres differ in number)");
    for (double r : sh.clump.radii)
      if (!(r > 0)) fail(s, where + "a clump sphere has a non-positive radius");
    if (!(sh.mass.volume > 0)) fail(s, where + "volume must be positive");
    // Sylvester's criterion: all leading minors positive.
    const Eigen::Matrix3d& in = sh.mass.inertia;
    if (!(in(0, 0) > 0 && in.topLeftCorner<2, 2>().determinant() > 0 && in.determinant() > 0))
      fail(s, where + "the inertia tensor is not positive definite");
  }
  for (int d = 0; d < 3; ++d)
    if (!(s.box_hi[d] > s.box_lo[d]))
      fail(s, std::string("dem.box: the box is empty along ") + axis_name(d));
  (void)make_contact_model(p.material, s.file);
  if (p.buoyancy_fluid_density > 0 && p.gravity == std::array<double, 3>{0, 0, 0})
    fail(s, "dem.buoyancy_fluid_density: buoyancy needs a non-zero dem.gravity");

  // Walls: not on periodic axes, inside the box.
  for (size_t w = 0; w < p.walls.size(); ++w) {
    const auto& wall = p.walls[w];
    const std::string where = "dem.walls[" + std::to_string(w) + "]: ";
    if (p.periodic[wall.axis])
      fail(s, where + "a wall normal to " + axis_name(wall.axis) + " on a periodic axis");
    const double pos =
        wall.position.value_or(wall.lower ? s.box_lo[wall.axis] : s.box_hi[wall.axis]);
    if (pos < s.box_lo[wall.axis] || pos > s.box_hi[wall.axis])
      fail(s, where + "position " + std::to_string(pos) + " lies outside the box");
  }

  // Bodies: known shape, inside the box, clear of walls.
  std::vector<Eigen::Matrix3d> rot(s.bodies.size());
  double max_extent = 0;
  for (size_t i = 0; i < s.bodies.size(); ++i) {
    const auto& b = s.bodies[i];
    if (b.shape < 0 || static_cast<size_t>(b.shape) >= s.shapes.size())
      fail(s, "bodies: " + body_name(i) + " refers to shape " + std::to_string(b.shape) +
                  " which does not exist");
    if (!(b.density > 0)) fail(s, "bodies: " + body_name(i) + " needs a positive density");
    const Shape& sh = s.shapes[static_cast<size_t>(b.shape)];
    max_extent = std::max(max_extent, clump_extent(sh));
    rot[i] = to_eigen(b.orientation).normalized().toRotationMatrix();
    const auto ext = rotated_extent(sh, rot[i]);
    for (int d = 0; d < 3; ++d) {
      const double x = b.position[d];
      const bool inside = p.periodic[d]
                              ? (x >= s.box_lo[d] && x < s.box_hi[d])
                              : (x + ext[d][0] >= s.box_lo[d] && x + ext[d][1] <= s.box_hi[d]);
      if (!inside) {
        std::ostringstream m;
        m << "bodies: " << body_name(i) << " at (" << b.position[0] << ", " << b.position[1] << ", "
          << b.position[2] << ") " << (p.periodic[d] ? "has its centre" : "reaches")
          << " outside the box along " << axis_name(d) << " [" << s.box_lo[d] << ", " << s.box_hi[d]
          << "]";
        fail(s, m.str());
      }
    }
    for (size_t w = 0; w < p.walls.size(); ++w) {
      const auto& wall = p.walls[w];
      const int d = wall.axis;
      const double pos = wall.position.value_or(wall.lower ? s.box_lo[d] : s.box_hi[d]);
      const bool clear =
          wall.lower ? b.position[d] + ext[d][0] >= pos : b.position[d] + ext[d][1] <= pos;
      if (!clear)
        fail(s, "bodies: " + body_name(i) + " overlaps dem.walls[" + std::to_string(w) + "] (" +
                    axis_name(d) + " = " + std::to_string(pos) + ")");
    }
  }

  // Body-body overlap of clump spheres: cell list on centres (cell = two extents), minimum
  // image on periodic axes.
  const double h = 2 * max_extent;
  std::array<long, 3> nc{};
  std::array<double, 3> len{};
  for (int d = 0; d < 3; ++d) {
    len[d] = s.box_hi[d] - s.box_lo[d];
    nc[d] = std::max(1L, static_cast<long>(len[d] / h));
  }
  auto cell = [&](const std::array<double, 3>& x, int d) {
    return std::clamp(static_cast<long>((x[d] - s.box_lo[d]) / len[d] * nc[d]), 0L, nc[d] - 1);
  };
  std::unordered_map<long, std::vector<size_t>> grid;
  auto key = [&](long i, long j, long k) { return i + nc[0] * (j + nc[1] * k); };
  for (size_t i = 0; i < s.bodies.size(); ++i)
    grid[key(cell(s.bodies[i].position, 0), cell(s.bodies[i].position, 1),
             cell(s.bodies[i].position, 2))]
        .push_back(i);
  auto overlap = [&](size_t a, size_t b) {
    const auto& A = s.bodies[a];
    const auto& B = s.bodies[b];
    const Shape& sa = s.shapes[static_cast<size_t>(A.shape)];
    const Shape& sb = s.shapes[static_cast<size_t>(B.shape)];
    Eigen::Vector3d dxy = to_eigen(B.position) - to_eigen(A.position);
    for (int d = 0; d < 3; ++d)
      if (p.periodic[d]) dxy[d] -= len[d] * std::round(dxy[d] / len[d]);
    if (dxy.norm() >= clump_extent(sa) + clump_extent(sb)) return false;
    for (size_t u = 0; u < sa.clump.centers.size(); ++u)
      for (size_t v = 0; v < sb.clump.centers.size(); ++v) {
        const Eigen::Vector3d ca = rot[a] * sa.clump.centers[u];
        const Eigen::Vector3d cb = dxy + rot[b] * sb.clump.centers[v];
        if ((cb - ca).norm() < sa.clump.radii[u] + sb.clump.radii[v]) return true;
      }
    return false;
  };
  for (size_t i = 0; i < s.bodies.size(); ++i) {
    const long ci = cell(s.bodies[i].position, 0), cj = cell(s.bodies[i].position, 1),
               ck = cell(s.bodies[i].position, 2);
    for (long dk = -1; dk <= 1; ++dk)
      for (long dj = -1; dj <= 1; ++dj)
        for (long di = -1; di <= 1; ++di) {
          std::array<long, 3> c{ci + di, cj + dj, ck + dk};
          bool skip = false;
          for (int d = 0; d < 3; ++d) {
            if (c[d] < 0 || c[d] >= nc[d]) {
              if (!p.periodic[d]) skip = true;
              c[d] = (c[d] + nc[d]) % nc[d];
            }
          }
          if (skip) continue;
          auto it = grid.find(key(c[0], c[1], c[2]));
          if (it == grid.end()) continue;
          for (size_t j : it->second)
            if (j > i && overlap(i, j))
              fail(s, "bodies: " + body_name(i) + " and " + body_name(j) + " overlap initially");
        }
  }
  if (!(dem_time_step(s) > 0)) fail(s, "dem.dt: the DEM time step must be positive");
  check_lubrication_step(s, dem_time_step(s));
}

double time_step_radius(const Shape& shape, const DemParams& params) {
  if (params.dt_rule == "particle")
    return std::cbrt(3.0 * shape.mass.volume / (4.0 * std::numbers::pi));
  return smallest_sphere_radius(shape);
}

double dem_time_step(const DemSetup& setup) {
  if (setup.params.dt > 0) return setup.params.dt;
  double t = std::numeric_limits<double>::infinity();
  for (const auto& b : setup.bodies) {
    const Shape& sh = setup.shapes[static_cast<size_t>(b.shape)];
    t = std::min(
        t, rayleigh_time(time_step_radius(sh, setup.params), b.density, setup.params.material));
  }
  return setup.params.dt_fraction * t;
}

}  // namespace lbdem
