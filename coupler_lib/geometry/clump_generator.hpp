#pragma once
// Multi-sphere clumps from a solid (docs/user-guide.md, "Shapes and clumps", for the methods and
// measured errors).
//
// surface: equal spheres centred on the boundary points of a regular grid laid over the
//   solid eroded by the sphere radius r, so the spheres touch the surface from inside.
//   With `grid` = n points per edge of the (eroded) bounding box, spacing
//   s = (L - 2 r) / (n - 1), r = radius_ratio * s, i.e. s = L / (n - 1 + 2 radius_ratio).
//   For a cube these are the n^3 - (n-2)^3 = 6n^2 - 12n + 8 points on the faces of an n^3
//   grid; with the centre sphere: n = 10 -> 489, n = 20 -> 2169 (the paper's cubes).
// fill: greedy largest-inscribed-sphere filling on the voxelization, in the spirit of the
//   CLUMP library's Euclidean-distance-transform method: repeatedly take the not yet
//   covered solid voxel farthest from the surface, move its centre within the cell to the
//   deepest point, place a sphere there with radius equal to the exact distance to the
//   surface, and mark the voxels it covers, until `spheres` are placed or all are covered.
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"

namespace lbdem {

struct SurfaceClumpOptions {
  int grid = 10;              // points per edge of the eroded bounding box (>= 2)
  double radius_ratio = 1.0;  // sphere radius / grid spacing
  bool center_sphere = true;  // add the largest inscribed sphere at the deepest voxel
};

struct FillClumpOptions {
  int spheres = 100;  // target count; fewer if every solid voxel is covered earlier
};

// `voxels` is the solid's voxelization in the input frame; the clump is returned in the
// input frame (subtract the centroid to get the shape frame).
Clump surface_clump(const SolidGeometry& solid, const Voxels& voxels,
                    const SurfaceClumpOptions& options);
Clump fill_clump(const SolidGeometry& solid, const Voxels& voxels, const FillClumpOptions& options);

// Shape error of a clump against a voxelization in the same frame: volume of the symmetric
// difference of the clump union and the solid voxels relative to the solid volume, and the
// two-sided (Hausdorff) distance between the two: for each voxel of that symmetric
// difference, the distance to the nearest voxel of the other body (distance transform minus
// h/2, so resolution about h/2). Cavities enclosed by the spheres
// (the inside of a surface clump) count as part of the clump: no other body can reach them.
ClumpQuality clump_quality(const Clump& clump, const Voxels& voxels);

// Voxels (same lattice) whose centre lies in at least one sphere of the clump.
Voxels clump_voxels(const Clump& clump, const Voxels& lattice);

Clump translated(Clump c, const Eigen::Vector3d& shift);

}  // namespace lbdem
