#pragma once
// Closed, outward-oriented triangle meshes of simple solids, centred at the origin: used
// to ship STL files for the built-in shapes and by the tests.
#include <Eigen/Dense>

#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

// Axis-aligned box with the given edges, 12 triangles.
TriangleMesh box_mesh(const Eigen::Vector3d& edges);

// Icosahedron refined `levels` times (each level splits every triangle into four and
// projects the new vertices onto the sphere): 20 * 4^levels triangles, all vertices at
// distance `radius`, so the solid is inscribed in the sphere.
TriangleMesh icosphere_mesh(double radius, int levels);

// Regular octahedron |x| + |y| + |z| <= a (vertices on the axes at distance a).
TriangleMesh octahedron_mesh(double a);

// Torus about the z axis: centre-line radius `ring`, tube radius `tube` < ring, with
// `around` segments along the ring and `across` around the tube (2 around across triangles);
// all vertices on the torus, so the solid is inscribed in it.
TriangleMesh torus_mesh(double ring, double tube, int around, int across);

// Apply x -> R x + t to every vertex.
void transform_mesh(TriangleMesh& mesh, const Eigen::Matrix3d& R, const Eigen::Vector3d& t);

}  // namespace lbdem
