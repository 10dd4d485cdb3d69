#pragma once
// One call from scene parameters to everything a side needs about a shape: the exact mass
// properties, the reference voxelization in the shape frame (with the volume it embeds), the
// contact clump and its quality, and the bounding radius. Both binaries call this with the same
// spacing and get identical numbers. With hydrodynamic_scale != 1 or hydrodynamic_offset != 0,
// `voxels`, `reference_volume` and `bounding_radius` are those of the scaled and offset shape
// (what the fluid sees); mass properties and the clump stay the true shape's.
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/shape_params.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"

namespace lbdem {

// The solid described by the parameters (reads and checks the STL for kind stl).
SolidGeometry make_solid(const ShapeParams& params);

// The same shape scaled by `factor` about the origin of its input frame.
ShapeParams scaled_params(const ShapeParams& params, double factor);

// The same shape with its surface moved inward by `offset` m (outward when negative): exact for
// spheres, cubes and cuboids (a box eroded by a ball is a box); semi-axes reduced by `offset`
// for ellipsoids (the parallel surface of an ellipsoid is not an ellipsoid; the difference is
// second order in offset / semi-axis); for meshes a scale about the input frame's origin that
// removes the same volume to first order, 1 - offset S / (3 V) (S area, V volume).
ShapeParams offset_params(const ShapeParams& params, double offset);

// Throws ShapeError (message starts with params.where) for unreadable or invalid input.
Shape build_shape(const ShapeParams& params, double voxel_spacing);

}  // namespace lbdem
