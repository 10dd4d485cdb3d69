#include "coupler_lib/geometry/display_surface.hpp"

#include <stdexcept>

#include "coupler_lib/geometry/shape_kinds.hpp"

namespace lbdem {

TriangleMesh display_surface(const ShapeParams& params, const Eigen::Vector3d& centroid) {
  TriangleMesh m = rules_of(params.kind).surface(params);
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
