#include "coupler_lib/geometry/shape_kinds.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "coupler_lib/geometry/mesh_check.hpp"
#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/stl_io.hpp"

namespace lbdem {

namespace {

// Refinement of the round shapes' display surface: 320 triangles keep a sphere visibly round
// in a picture while a body costs 162 vertices per snapshot.
constexpr int kDisplayLevels = 2;

Eigen::Vector3d extents_of(const ShapeParams& p) {
  return {p.extents[0], p.extents[1], p.extents[2]};
}

const ShapeKindRules kSphere{
    .semi_axes = true,
    .offset_is_a_parameter = true,
    .solid = [](const ShapeParams& p) { return SolidGeometry::sphere(p.size / 2); },
    .surface = [](const ShapeParams& p) { return icosphere_mesh(p.extents[0], kDisplayLevels); },
    .extent =
        [](const ShapeParams& p) {
          const double a = p.size;
          return std::optional<ShapeExtent>({0.5 * a, std::numbers::pi * a * a * a / 6.0});
        },
};

const ShapeKindRules kCube{
    .semi_axes = false,
    .offset_is_a_parameter = true,
    .solid =
        [](const ShapeParams& p) {
          return SolidGeometry::cuboid(Eigen::Vector3d::Constant(p.size));
        },
    .surface = [](const ShapeParams& p) { return box_mesh(extents_of(p)); },
    .extent =
        [](const ShapeParams& p) {
          const double a = p.size;
          return std::optional<ShapeExtent>({0.5 * std::sqrt(3.0) * a, a * a * a});
        },
};

const ShapeKindRules kCuboid{
    .semi_axes = false,
    .offset_is_a_parameter = true,
    .solid = [](const ShapeParams& p) { return SolidGeometry::cuboid(extents_of(p)); },
    .surface = [](const ShapeParams& p) { return box_mesh(extents_of(p)); },
    .extent =
        [](const ShapeParams& p) {
          const auto& e = p.extents;
          return std::optional<ShapeExtent>(
              {0.5 * std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]), e[0] * e[1] * e[2]});
        },
};

const ShapeKindRules kEllipsoid{
    .semi_axes = true,
    .offset_is_a_parameter = false,
    .solid = [](const ShapeParams& p) { return SolidGeometry::ellipsoid(extents_of(p)); },
    .surface =
        [](const ShapeParams& p) {
          TriangleMesh m = icosphere_mesh(1.0, kDisplayLevels);
          for (auto& v : m.vertices) v = v.cwiseProduct(extents_of(p));
          return m;
        },
    .extent =
        [](const ShapeParams& p) {
          const auto& e = p.extents;
          return std::optional<ShapeExtent>(
              {std::max({e[0], e[1], e[2]}), 4.0 / 3.0 * std::numbers::pi * e[0] * e[1] * e[2]});
        },
};

SolidGeometry stl_solid(const ShapeParams& p) {
  TriangleMesh mesh = read_stl(p.file);
  check_closed_oriented(mesh, p.file);
  scale_mesh(mesh, p.scale);
  return SolidGeometry::mesh(std::move(mesh));
}

const ShapeKindRules kStl{
    .semi_axes = false,
    .offset_is_a_parameter = false,
    .solid = stl_solid,
    .surface = [](const ShapeParams& p) { return stl_solid(p).triangles(); },
    .extent = [](const ShapeParams&) { return std::optional<ShapeExtent>(); },
};

}  // namespace

const ShapeKindRules& rules_of(ShapeKind kind) {
  // In the order of the enum (shape_params.hpp).
  static const std::array<const ShapeKindRules*, 5> rows{&kSphere, &kCube, &kCuboid, &kEllipsoid,
                                                         &kStl};
  const auto i = static_cast<std::size_t>(kind);
  if (i >= rows.size()) throw std::logic_error("rules_of: shape kind out of range");
  return *rows[i];
}

}  // namespace lbdem
