#pragma once
// Volume, centroid and inertia tensor of a shape, per unit density.
//
// * From the solid itself (what the DEM uses): closed forms for the analytic kinds and the
//   polyhedral integrals of a closed mesh (sums over the signed tetrahedra spanned by each
//   triangle and a reference point, by the divergence theorem). Exact up to round-off, so a
//   body of density rho has mass rho V whatever the lattice spacing (docs/method.md,
//   "Reference lattice").
// * From the reference voxelization (what the fluid embeds): each voxel weighs its solid
//   volume fraction; used to report how closely the fluid's body matches the DEM's.
// Principal axes from Eigen::SelfAdjointEigenSolver.
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"

namespace lbdem {

MassProperties mass_properties(const SolidGeometry& solid);
MassProperties mass_properties(const Voxels& voxels);

// Principal moments (ascending) and axes (columns, right-handed) of a symmetric tensor.
void principal_axes(const Eigen::Matrix3d& inertia, Eigen::Vector3d& moments,
                    Eigen::Matrix3d& axes);

// Max distance from `center` of any corner of a voxel holding solid (fill > 0).
double bounding_radius(const Voxels& voxels, const Eigen::Vector3d& center);

}  // namespace lbdem
