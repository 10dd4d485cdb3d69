#include "coupler_lib/geometry/mesh_check.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "coupler_lib/errors.hpp"

namespace lbdem {

namespace {

std::string point_text(const Eigen::Vector3d& p) {
  std::ostringstream s;
  s.precision(6);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

struct EdgeUse {
  int forward = 0;   // traversed from the smaller to the larger vertex index
  int backward = 0;  // traversed the other way
};

}  // namespace

void check_closed_oriented(const TriangleMesh& mesh, const std::string& file) {
  if (mesh.triangles.empty()) throw ShapeError(file + ": the mesh has no triangles");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const auto& a = mesh.vertices[tri[0]];
    const auto& b = mesh.vertices[tri[1]];
    const auto& c = mesh.vertices[tri[2]];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] ||
        (b - a).cross(c - a).norm() == 0.0)
      throw ShapeError(file + ": triangle " + std::to_string(t) + " is degenerate (zero area) at " +
                       point_text((a + b + c) / 3.0));
  }

  std::map<std::pair<int, int>, EdgeUse> edges;
  for (const auto& tri : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const int u = tri[e], v = tri[(e + 1) % 3];
      auto& use = edges[{std::min(u, v), std::max(u, v)}];
      (u < v ? use.forward : use.backward)++;
    }
  }
  int open = 0, nonmanifold = 0, misoriented = 0;
  Eigen::Vector3d first_open, first_nonmanifold, first_misoriented;
  for (const auto& [key, use] : edges) {
    const Eigen::Vector3d mid = 0.5 * (mesh.vertices[key.first] + mesh.vertices[key.second]);
    const int n = use.forward + use.backward;
    if (n == 1) {
      if (open++ == 0) first_open = mid;
    } else if (n > 2) {
      if (nonmanifold++ == 0) first_nonmanifold = mid;
    } else if (use.forward != 1) {
      if (misoriented++ == 0) first_misoriented = mid;
    }
  }
  if (open > 0)
    throw ShapeError(file + ": " + std::to_string(open) + " open edge" + (open > 1 ? "s" : "") +
                     " (used by one triangle only), first at " + point_text(first_open) +
                     "; the surface must be closed");
  if (nonmanifold > 0)
    throw ShapeError(file + ": " + std::to_string(nonmanifold) + " non-manifold edge" +
                     (nonmanifold > 1 ? "s" : "") +
                     " (shared by more than two triangles), first at " +
                     point_text(first_nonmanifold));
  if (misoriented > 0)
    throw ShapeError(file + ": " + std::to_string(misoriented) + " inconsistently oriented edge" +
                     (misoriented > 1 ? "s" : "") +
                     " (both triangles traverse it in the same direction), first at " +
                     point_text(first_misoriented) + "; flip the offending triangles");
  const double vol = signed_volume(mesh);
  if (!(vol > 0))
    throw ShapeError(file + ": the enclosed volume is " + std::to_string(vol) +
                     " (not positive): the triangles are ordered clockwise seen from outside "
                     "(normals point inwards); reverse their vertex order");
}

}  // namespace lbdem
