#pragma once
// Inside/outside voxelization on a cell-centred lattice (input frame), with the solid volume
// fraction of every voxel (voxel_fill.hpp).
//
// The lattice is centred on the middle of the geometry's bounding box, with
// ceil(extent / h) voxels across each axis plus `pad` empty layers on every side, so a box
// whose edges are multiples of h is voxelized exactly. Meshes use ray parity along z per
// column of voxel centres; ties at edges and vertices are broken by a fixed infinitesimal
// shift of the ray (x + eps, y + eps^2) evaluated with each edge in one canonical direction,
// so a ray through a shared edge or vertex is counted exactly once.
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"
#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

// The empty lattice (solid flags 0, no fill) centred on the box [lo, hi], ceil(extent / h)
// voxels across plus `pad` layers on every side.
Voxels empty_lattice(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double h, int pad);

Voxels voxelize(const SolidGeometry& geometry, double h, int pad = 2);
Voxels voxelize_mesh(const TriangleMesh& mesh, double h, int pad = 2);

// The same lattice with each voxel's fill replaced by the solid fraction of the cube of side 2 h
// centred on it (h the lattice spacing), each voxel's fill taken as spread evenly over it: per
// axis that cube covers the voxel (weight 1/2) and half of each neighbour (1/4 each). Exact
// where the fills are 0 or 1; the total fill is kept where the outer layer is empty. The
// fluid's reference lattice (build_shape.hpp) is this at h = dx / 4.
Voxels box_averaged(Voxels v);

// The same lattice, translated by -shift (e.g. into the shape frame: shift = centroid).
Voxels translated(Voxels v, const Eigen::Vector3d& shift);

}  // namespace lbdem
