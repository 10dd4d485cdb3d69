#pragma once
// An indexed triangle surface. Triangles list vertex indices counter-clockwise seen from
// outside (outward normals), as STL requires.
#include <Eigen/Dense>

#include <array>
#include <vector>

namespace lbdem {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Volume enclosed by a closed mesh (divergence theorem); positive for outward normals.
double signed_volume(const TriangleMesh& mesh);

// Sum of the triangle areas.
double surface_area(const TriangleMesh& mesh);

// Axis-aligned bounds of the vertices.
void bounding_box(const TriangleMesh& mesh, Eigen::Vector3d& lo, Eigen::Vector3d& hi);

// Multiply every vertex by s.
void scale_mesh(TriangleMesh& mesh, double s);

}  // namespace lbdem
