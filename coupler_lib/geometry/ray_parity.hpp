#pragma once
// The robust crossing test behind mesh inside/outside: does the vertical line through
// (x, y) pierce triangle (a, b, c), and at which z?
//
// Each edge's side test is evaluated with the edge in one canonical direction (smaller
// vertex index first), so the two triangles sharing an edge see exactly opposite signs.
// Exact zeros (the line through an edge or vertex) are resolved as if the line were moved
// by (eps, eps^2) (simulation of simplicity), so such a line is counted in exactly one of
// the triangles it touches and ray parity stays correct on grid-aligned meshes.
#include <Eigen/Dense>

#include <array>

namespace lbdem {

// `idx` are the vertex indices of a, b, c (for the canonical edge direction). Returns false
// for triangles seen edge-on (zero projected area). On true, z is the height of the
// triangle's plane at (x, y).
bool pierces_column(const std::array<int, 3>& idx, const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b, const Eigen::Vector3d& c, double x, double y,
                    double& z);

}  // namespace lbdem
