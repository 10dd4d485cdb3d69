#pragma once
// What differs between shape kinds once a shape's parameters are read, one row per kind in
// shape_kinds.cpp: the only dispatch on ShapeKind past the scene reader (whose per-kind keys
// are in scene/shapes_section.cpp). A new kind is a new row there and a new reader branch.
#include <optional>

#include "coupler_lib/geometry/shape_params.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"
#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

// Bounding radius and volume of a shape, known without building it.
struct ShapeExtent {
  double bounding_radius = 0;  // m, circumscribed sphere about the centroid
  double volume = 0;           // m^3
};

struct ShapeKindRules {
  // ShapeParams::extents holds semi-axes (round shapes) rather than edges.
  bool semi_axes = false;
  // The surface moved along its normal is a shape of the same kind (a sphere, cube or cuboid
  // with other size parameters: build_shape.hpp, offset_params); other kinds are eroded or
  // dilated on the fluid's lattice (offset_voxels.hpp).
  bool offset_is_a_parameter = false;
  // The solid (reads and checks the STL for kind stl).
  SolidGeometry (*solid)(const ShapeParams&) = nullptr;
  // The surface a viewer draws, in the shape's input frame (display_surface.hpp).
  TriangleMesh (*surface)(const ShapeParams&) = nullptr;
  // Bounding radius and volume from the parameters alone; empty when only the built shape
  // knows them (a mesh).
  std::optional<ShapeExtent> (*extent)(const ShapeParams&) = nullptr;
};

const ShapeKindRules& rules_of(ShapeKind kind);

inline bool extents_are_semi_axes(ShapeKind kind) {
  return rules_of(kind).semi_axes;
}
inline bool offset_is_a_parameter(ShapeKind kind) {
  return rules_of(kind).offset_is_a_parameter;
}
inline SolidGeometry make_solid(const ShapeParams& p) {
  return rules_of(p.kind).solid(p);
}
inline std::optional<ShapeExtent> analytic_extent(const ShapeParams& p) {
  return rules_of(p.kind).extent(p);
}

}  // namespace lbdem
