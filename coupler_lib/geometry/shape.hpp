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
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lbdem {

// Inside/outside on a cell-centred lattice of spacing h: voxel (i,j,k) has its centre at
// origin + h * (i, j, k) in the shape frame; solid[i + n0*(j + n1*k)] is 1 inside.
// Built voxelizations keep at least one layer of empty voxels on every side.
struct Voxels {
  double h = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::array<int, 3> n{0, 0, 0};
  std::vector<std::uint8_t> solid;

  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(n[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1]) * k);
  }
  Eigen::Vector3d center(int i, int j, int k) const {
    return origin + h * Eigen::Vector3d(i, j, k);
  }
  // Solid flag of the voxel whose cell contains p (same frame as origin); 0 off the lattice.
  // This is the reference-porosity lookup: porosity d = 1 - solid_at(p).
  std::uint8_t solid_at(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = (p - origin) / h;
    const double fi = std::floor(q.x() + 0.5), fj = std::floor(q.y() + 0.5),
                 fk = std::floor(q.z() + 0.5);
    if (!(fi >= 0 && fj >= 0 && fk >= 0 && fi < n[0] && fj < n[1] && fk < n[2])) return 0;
    return solid[index(static_cast<int>(fi), static_cast<int>(fj), static_cast<int>(fk))];
  }
  std::size_t count() const {
    std::size_t c = 0;
    for (auto s : solid) c += s;
    return c;
  }
};

// Per unit density: multiply volume and inertia by the body density to get kg and kg m^2.
struct MassProperties {
  double volume = 0;                                   // m^3
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // in the input frame, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();   // about the centroid, shape frame, m^5
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();   // ascending, m^5
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();  // columns, shape frame,
                                                                 // a rotation (det = +1)
};

// Multi-sphere representation for contacts (shape frame, relative to the centroid).
struct Clump {
  std::vector<Eigen::Vector3d> centers;
  std::vector<double> radii;
  std::size_t size() const { return radii.size(); }
};

// How well a clump represents its shape, measured on the shape's voxel lattice.
struct ClumpQuality {
  double volume_error = 0;     // |clump union XOR shape| / shape volume
  double max_deviation = 0;    // m, largest distance of a mismatched voxel from the surface
  double lattice_spacing = 0;  // m, h of the lattice used for both numbers
};

struct Shape {
  std::string name;
  Voxels voxels;  // reference lattice, in the shape frame
  MassProperties mass;
  Clump clump;
  ClumpQuality clump_quality;
  std::string clump_source;    // "file <path>", "surface n=10 ...", "fill spheres=100 ..."
  double bounding_radius = 0;  // m: max distance of any solid voxel corner from the centroid
};

}  // namespace lbdem
