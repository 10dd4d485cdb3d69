#pragma once
// A body shape as both sides use it: the DEM's mass properties come from the solid itself
// (exact), the fluid's reference porosity from a voxelization that holds each voxel's solid
// volume fraction, so that the volume the fluid embeds matches the DEM's to a fraction of a
// percent at any resolution (docs/method.md, "Reference lattice"; the paper's appendix
// "Representation of a particle in the fluid" uses 0/1 voxels for both, which puts the
// volume of a cube of 19.4 reference cells 9.6 % high or 6 % low depending on alignment).
//
// Shape frame: the frame of the STL (or analytic definition) translated so that the
// centroid is the origin; axes are not rotated. A body's orientation quaternion maps this
// frame to the space frame.
#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lbdem {

// A cell-centred lattice of spacing h: voxel (i,j,k) is the cube of side h centred at
// origin + h * (i, j, k) in the shape frame. solid[i + n0*(j + n1*k)] is 1 where the centre is
// inside (what the clump generator and distance transforms read); fill[...] is the fraction
// of the voxel's volume inside the solid, in [0, 1] (what mass properties of the lattice and
// the fluid's reference porosity read). Built voxelizations keep at least one layer of empty
// voxels on every side.
struct Voxels {
  double h = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  std::array<int, 3> n{0, 0, 0};
  std::vector<std::uint8_t> solid;
  std::vector<float> fill;

  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(n[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1]) * k);
  }
  Eigen::Vector3d center(int i, int j, int k) const {
    return origin + h * Eigen::Vector3d(i, j, k);
  }
  // Solid flag of the voxel whose cell contains p (same frame as origin); 0 off the lattice.
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
  // The fluid's reference lattice, in the shape frame: voxels of half the shape's voxel spacing
  // (dx / 4 in a scene with a fluid), each holding the solid fraction of the box of side
  // voxel_spacing (the stencil spacing dx / 2) centred on it, so that the nearest lookup moves
  // no stencil point by more than dx / 8 (docs/method.md, "Reference lattice").
  Voxels voxels;
  double voxel_spacing = 0;     // m, the solid's voxelization (clump, its quality)
  MassProperties mass;          // of the solid itself (exact)
  double reference_volume = 0;  // m^3, sum of fill h^3: the volume the fluid embeds
  Clump clump;
  ClumpQuality clump_quality;
  std::string clump_source;    // "file <path>", "surface n=10 ...", "fill spheres=100 ..."
  double bounding_radius = 0;  // m: max distance of any corner of a reference voxel with fill
};

}  // namespace lbdem
