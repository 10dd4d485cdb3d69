#include "coupler_lib/geometry/display_surface.hpp"

#include <stdexcept>

#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/geometry/mesh_primitives.hpp"

namespace lbdem {

TriangleMesh display_surface(const ShapeParams& params, const Eigen::Vector3d& centroid) {
  // Refinement of the round shapes: 320 triangles keep a sphere visibly round in a picture
  // while a body costs 162 vertices per snapshot.
  constexpr int kLevels = 2;
  const Eigen::Vector3d e(params.extents[0], params.extents[1], params.extents[2]);
  TriangleMesh m;
  switch (params.kind) {
    case ShapeKind::sphere:
      m = icosphere_mesh(e.x(), kLevels);
      break;
    case ShapeKind::ellipsoid:
      m = icosphere_mesh(1.0, kLevels);
      for (auto& v : m.vertices) v = v.cwiseProduct(e);
      break;
    case ShapeKind::cube:
    case ShapeKind::cuboid:
      m = box_mesh(e);
      break;
    case ShapeKind::stl:
      m = make_solid(params).triangles();
      break;
  }
  for (auto& v : m.vertices) v -= centroid;
  return m;
}

std::vector<TriangleMesh> display_surfaces(const std::vector<ShapeParams>& params,
                                           const std::vector<Shape>& shapes) {
  if (params.size() != shapes.size())
    throw std::logic_error("display_surfaces: shape parameters and shapes differ in number");
  std::vector<TriangleMesh> out;
  for (size_t i = 0; i < params.size(); ++i)
    out.push_back(display_surface(params[i], shapes[i].mass.centroid));
  return out;
}

}  // namespace lbdem
