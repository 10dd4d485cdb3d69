#pragma once
// The fluid's view of a body whose surface is moved along its normal by a signed distance
// (the band's hydrodynamic radius calibration, docs/method.md): the parallel body
//   offset > 0: {x inside the solid, at least offset from its surface}  (erosion),
//   offset < 0: {x inside the solid or within |offset| of it}           (dilation),
// voxelized with its solid volume fractions in the solid's own frame, on a lattice centred on
// the parallel body's bounding box ([lower + offset, upper - offset]).
// * Analytic solids: the point test above, from SolidGeometry::inside and the exact
//   distance_to_surface; fractions sampled like a sphere's (voxel_fill.hpp). |s - offset|,
//   with s the signed distance (positive inside), bounds the distance to the parallel surface
//   from below, which is what picks the voxels to sample.
// * Meshes: the same sub-columns as a mesh's fill (voxel_fill.hpp), each cut exactly along z:
//   the mesh's inside intervals minus (erosion) or plus (dilation) the intervals where the
//   line comes within |offset| of a triangle (triangle_band.hpp). Exact for any closed mesh,
//   concave parts included: the hole of a torus widens as its tube thins.
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"

namespace lbdem {

// Throws ShapeError when the offset leaves an empty bounding box.
Voxels voxelize_offset(const SolidGeometry& solid, double offset, double h, int pad = 2);

}  // namespace lbdem
