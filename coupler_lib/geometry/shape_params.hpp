#pragma once
// The parameters that describe one shape and its contact clump, whether they come from a
// scene's `shapes:` catalogue (coupler_lib/scene/shapes_section.hpp) or from clump_gen's
// command line. Plain data; build_shape.hpp turns them into a Shape.
#include <array>
#include <string>

#include "coupler_lib/words.hpp"

namespace lbdem {

enum class ShapeKind { sphere, cube, cuboid, ellipsoid, stl };
inline constexpr WordTable<ShapeKind, 5> kShapeKindWords{{{"sphere", ShapeKind::sphere},
                                                          {"cube", ShapeKind::cube},
                                                          {"cuboid", ShapeKind::cuboid},
                                                          {"ellipsoid", ShapeKind::ellipsoid},
                                                          {"stl", ShapeKind::stl}}};

// Where a shape's contact clump comes from: the shape's own default (an exact sphere for a
// sphere, a fill otherwise), a clump file, or one of the two generators (scene: clump.method).
enum class ClumpSource { shape_default, file, surface, fill };
inline constexpr WordTable<ClumpSource, 2> kClumpMethodWords{
    {{"surface", ClumpSource::surface}, {"fill", ClumpSource::fill}}};

// How the contact clump of a shape is obtained.
struct ClumpParams {
  ClumpSource source = ClumpSource::shape_default;
  std::string file;           // absolute (resolved against the scene's folder)
  double scale = 1;           // file coordinates and radii are multiplied by this
  int spheres = 0;            // fill: target sphere count
  int grid = 0;               // surface: grid points per edge of the bounding box
  double radius_ratio = 1;    // surface: sphere radius / grid spacing
  bool center_sphere = true;  // surface: add the largest inscribed sphere
};

struct ShapeParams {
  std::string name;
  ShapeKind kind = ShapeKind::sphere;
  // Characteristic length in m: sphere diameter, cube edge, longest cuboid edge, longest
  // ellipsoid axis (2 a_max); for stl, the longest scaled bounding-box edge (the file is
  // read and its bounds taken while parsing).
  double size = 0;
  // m: cube/cuboid edges, sphere/ellipsoid semi-axes (extents_are_semi_axes, shape_kinds.hpp), stl
  // scaled bounding-box edges
  std::array<double, 3> extents{0, 0, 0};
  std::string file;       // stl: absolute path
  double scale = 1;       // stl: vertex coordinates are multiplied by this
  double voxel_size = 0;  // m; 0: use the default (scene/shape_catalogue.hpp)
  // The fluid sees the shape scaled by this about its centroid; mass, inertia and contacts keep
  // the true shape (docs/lubrication.md, "Hydrodynamic radius").
  double hydrodynamic_scale = 1;
  // m: the fluid's shape is then moved inward by this distance normal to its surface (negative:
  // outward); the calibrated hydrodynamic radius of the HLBM band (docs/method.md, "Hydrodynamic
  // radius calibration"); build_shape.hpp and offset_voxels.hpp say how each kind is moved.
  double hydrodynamic_offset = 0;
  ClumpParams clump;
  std::string where;  // "scene.yaml:12: shapes[0]", for errors found after parsing
};

}  // namespace lbdem
