#pragma once
// A solid body as a geometric object: analytic (sphere, cuboid, ellipsoid, centred at the
// origin, axes along x, y, z) or a closed triangle mesh. Gives the exact inside test, the
// exact distance to the surface and the bounds; voxelize() turns it into Voxels.
#include <Eigen/Dense>

#include <array>
#include <memory>
#include <string>

#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

class SolidGeometry {
 public:
  enum class Kind { sphere, cuboid, ellipsoid, mesh };

  static SolidGeometry sphere(double radius);
  static SolidGeometry cuboid(const Eigen::Vector3d& edges);
  static SolidGeometry ellipsoid(const Eigen::Vector3d& semi_axes);
  // The mesh must already have passed check_closed_oriented.
  static SolidGeometry mesh(TriangleMesh mesh);

  Kind kind() const { return kind_; }
  const Eigen::Vector3d& parameters() const { return p_; }  // radius / edges / semi-axes
  const TriangleMesh& triangles() const { return *mesh_; }  // Kind::mesh only

  bool inside(const Eigen::Vector3d& x) const;
  // Unsigned Euclidean distance from x to the surface.
  double distance_to_surface(const Eigen::Vector3d& x) const;
  // Bounds lo <= distance_to_surface(x) <= hi without the exact distance where that is costly
  // (the ellipsoid's is an iterative root): x on the surface of the ellipsoid scaled by s about
  // its centre lies at least |1 - s| a_min from the surface (the support functions of the two
  // differ by |1 - s| h(u) >= |1 - s| a_min) and at most |x - x / s| (x / s is on it). The other
  // kinds give lo = hi = the exact distance.
  std::array<double, 2> distance_bounds(const Eigen::Vector3d& x) const;
  Eigen::Vector3d lower() const { return lo_; }
  Eigen::Vector3d upper() const { return hi_; }
  // Exact volume when known in closed form (analytic kinds and meshes), m^3.
  double exact_volume() const;
  std::string describe() const;

 private:
  Kind kind_ = Kind::sphere;
  Eigen::Vector3d p_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d lo_ = Eigen::Vector3d::Zero(), hi_ = Eigen::Vector3d::Zero();
  std::shared_ptr<const TriangleMesh> mesh_;
};

}  // namespace lbdem
