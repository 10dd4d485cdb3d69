#pragma once
// One call from scene parameters to everything a side needs about a shape: the exact mass
// properties, the fluid's reference lattice in the shape frame (voxels of half the given
// spacing holding box fills, shape.hpp; with the volume it embeds), the contact clump and its
// quality, and the bounding radius. Both binaries call this with the same spacing and get
// identical numbers. With hydrodynamic_scale != 1 or hydrodynamic_offset != 0,
// `voxels`, `reference_volume` and `bounding_radius` are those of the scaled and offset shape
// (what the fluid sees: the scaled shape centred on its centroid, then its surface moved along
// its normal by the offset); mass properties and the clump stay the true shape's.
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/shape_kinds.hpp"
#include "coupler_lib/geometry/shape_params.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"

namespace lbdem {

// The same shape scaled by `factor` about the origin of its input frame.
ShapeParams scaled_params(const ShapeParams& params, double factor);

// The same sphere, cube or cuboid (offset_is_a_parameter, shape_kinds.hpp; for a box moved
// outward the parallel body would round the edges this one keeps sharp) with its surface moved
// inward by `offset` m (outward when
// negative): radius or edges reduced by offset or 2 offset.
ShapeParams offset_params(const ShapeParams& params, double offset);

// Throws ShapeError (message starts with params.where) for unreadable or invalid input.
Shape build_shape(const ShapeParams& params, double voxel_spacing);

}  // namespace lbdem
