#pragma once
// The solid volume fraction of every voxel (Voxels::fill), which the fluid's reference
// porosity reads (docs/method.md, "Reference lattice"):
// * cuboid: exact, the product over the axes of the voxel's overlap with the edge interval;
// * sphere, ellipsoid: voxels whose centre lies within sqrt(3)/2 h of the surface are sampled
//   at 8^3 points, the others are wholly in or out;
// * mesh: 8 x 8 vertical sub-columns per voxel column (subcolumn_offset), each cut exactly
//   along z at its surface crossings (the ray-parity test of the voxelization).
// The volume error is then far below a percent: 0 for boxes, about 1e-4 for a sphere of 24
// voxels across (tests/coupler_lib/geometry/voxelize_test.cpp).
#include <functional>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"
#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

// Samples per axis in a voxel cut by a curved surface, and sub-columns per axis in a voxel
// column cut by a mesh.
inline constexpr int kFillSamplesPerAxis = 8;

// Where sub-column (u, w), 0 <= u, w < 8, samples its voxel column, in units of h from the
// column's corner: the sheared lattice ((u + (w + 1/2) / 8) / 8, (w + (u + 1/2) / 8) / 8). Its
// 64 columns all have different x and different y, so a face along a lattice axis is resolved
// to h / 64 (a square 8 x 8 grid resolves it to h / 8: a box face between sample rows lost up
// to h / 16 of every voxel layer it cuts, 3.5 % of the volume of a box 6.6 voxels across).
inline Eigen::Vector2d subcolumn_offset(int u, int w) {
  constexpr double n = kFillSamplesPerAxis;
  return {(u + (w + 0.5) / n) / n, (w + (u + 0.5) / n) / n};
}

// A fraction within 1e-5 of 0 or 1 set exactly: round-off of a voxel wholly out or in, so
// that the porosity deep inside a body is exactly 0 and far from it exactly 1 (the kernel
// takes the plain path there). The volume this moves is below 1e-5 h^3 per voxel.
float snapped_fraction(double f);

// Sets voxels.fill (sized like voxels.solid) for the given solid in the voxels' frame.
void fill_fractions(const SolidGeometry& solid, Voxels& voxels);
void fill_fractions(const TriangleMesh& mesh, Voxels& voxels);

// The sampled fill of a solid given by a point test: voxels whose centre lies more than
// sqrt(3)/2 h from the surface by `surface_distance_bound` (a lower bound on the distance is
// enough) keep their solid flag as fraction, the others are sampled at 8^3 points with
// `inside`. voxels.solid must be set.
using PointTest = std::function<bool(const Eigen::Vector3d&)>;
using DistanceBound = std::function<double(const Eigen::Vector3d&)>;
void fill_sampled(const PointTest& inside, const DistanceBound& surface_distance_bound,
                  Voxels& voxels);

}  // namespace lbdem
