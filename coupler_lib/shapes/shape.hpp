#pragma once
// A body shape as both sides use it: one voxelization gives the fluid's reference porosity
// and the DEM's mass properties, so fluid and DEM agree on volume, mass and inertia
// (paper, appendix "Representation of a particle in the fluid").
//
// Shape frame: the frame of the STL (or analytic definition) translated so that the
// voxelized centroid is the origin; axes are not rotated. A body's orientation quaternion
// maps this frame to the space frame.
#include <Eigen/Dense>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace lbdem {

// Inside/outside on a cell-centred lattice of spacing h: voxel (i,j,k) has its centre at
// origin + h * (i, j, k) in the shape frame; solid[i + n0*(j + n1*k)] is 1 inside.
struct Voxels {
  double h = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::array<int, 3> n{0, 0, 0};
  std::vector<std::uint8_t> solid;
};

// Per unit density: multiply inertia by the body density to get kg m^2.
struct MassProperties {
  double volume = 0;                                   // m^3
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // in the input frame, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // about the centroid, shape frame
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();  // columns, shape frame
};

// Multi-sphere representation for contacts (shape frame, relative to the centroid).
struct Clump {
  std::vector<Eigen::Vector3d> centers;
  std::vector<double> radii;
};

struct Shape {
  std::string name;
  Voxels voxels;  // reference lattice, in the shape frame
  MassProperties mass;
  Clump clump;
  double bounding_radius = 0;  // max distance of the surface from the centroid, m
};

}  // namespace lbdem
