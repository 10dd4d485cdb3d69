#include "coupler_lib/geometry/triangle_mesh.hpp"

#include <limits>

namespace lbdem {

double signed_volume(const TriangleMesh& mesh) {
  // Sum of signed tetrahedra (origin, a, b, c): V = 1/6 sum a . (b x c).
  double v = 0;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    const auto& b = mesh.vertices[t[1]];
    const auto& c = mesh.vertices[t[2]];
    v += a.dot(b.cross(c));
  }
  return v / 6.0;
}

double surface_area(const TriangleMesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return area;
}

void bounding_box(const TriangleMesh& mesh, Eigen::Vector3d& lo, Eigen::Vector3d& hi) {
  lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const auto& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}

void scale_mesh(TriangleMesh& mesh, double s) {
  for (auto& p : mesh.vertices) p *= s;
}

}  // namespace lbdem
