#pragma once
// The surface a viewer draws for a body: the shape's triangles in the shape frame (centroid at
// the origin, shape.hpp), which the DEM output places at each body's pose so that ParaView shows
// the bodies themselves rather than points. Spheres and ellipsoids are icospheres refined twice
// (320 triangles, vertices on the surface); cubes and cuboids are their 12 triangles; stl shapes
// are the file's own mesh, scaled as the scene says. The true shape, not the fluid's calibrated
// or scaled one.
#include <Eigen/Dense>

#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/shape_params.hpp"
#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

// `centroid`: the shape's centroid in its input frame (MassProperties::centroid).
TriangleMesh display_surface(const ShapeParams& params, const Eigen::Vector3d& centroid);

// One surface per shape of a catalogue: `params[i]` built as `shapes[i]`.
std::vector<TriangleMesh> display_surfaces(const std::vector<ShapeParams>& params,
                                           const std::vector<Shape>& shapes);

}  // namespace lbdem
