#pragma once
// Volume, centroid and inertia tensor of a voxelization: each solid voxel is a full cube of
// side h, so its own inertia h^2/6 * h^3 is added to the parallel-axis term (a box aligned
// with the lattice comes out exact). Principal axes from Eigen::SelfAdjointEigenSolver.
#include "coupler_lib/geometry/shape.hpp"

namespace lbdem {

MassProperties mass_properties(const Voxels& voxels);

// Principal moments (ascending) and axes (columns, right-handed) of a symmetric tensor.
void principal_axes(const Eigen::Matrix3d& inertia, Eigen::Vector3d& moments,
                    Eigen::Matrix3d& axes);

// Max distance from `center` of any corner of a solid voxel.
double bounding_radius(const Voxels& voxels, const Eigen::Vector3d& center);

}  // namespace lbdem
