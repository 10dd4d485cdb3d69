#pragma once
// Watertightness and orientation of a triangle mesh, required before voxelizing it.
#include <string>

#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

// Throws ShapeError with a message starting with `file` when the mesh is not closed (an edge
// not shared by exactly two triangles: "cube.stl: 3 open edges, first at (x, y, z)"), is
// inconsistently oriented (a shared edge traversed in the same direction by both
// triangles), has degenerate triangles, or encloses a non-positive volume (inside out).
void check_closed_oriented(const TriangleMesh& mesh, const std::string& file);

}  // namespace lbdem
