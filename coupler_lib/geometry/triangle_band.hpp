#pragma once
// Where a vertical line comes within a distance r of a triangle: the z range on the line
// (x, y, z) of the triangle's r-neighbourhood, the Minkowski sum of the triangle and a ball of
// radius r. That sum is convex, so the range is one interval; it is the union of the ranges of
// its pieces (a prism of half-thickness r over the triangle, a cylinder of radius r about each
// edge, a ball at each vertex), each found in closed form. The parallel body of a mesh
// (offset_voxels.hpp) cuts these intervals from, or adds them to, the mesh's inside intervals.
#include <Eigen/Dense>

namespace lbdem {

// True when the line meets the neighbourhood; [z0, z1] is then its range there.
bool near_triangle_interval(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c, double r, double x, double y, double& z0,
                            double& z1);

}  // namespace lbdem
