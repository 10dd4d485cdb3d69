#pragma once
// A solid body as a geometric object: analytic (sphere, cuboid, ellipsoid, centred at the
// origin, axes along x, y, z) or a closed triangle mesh. Gives the exact inside test, the
// exact distance to the surface and the bounds; voxelize() turns it into Voxels.
#include <Eigen/Dense>

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
