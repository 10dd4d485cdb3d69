#pragma once
// STL reading (ASCII and binary, detected from the content) and writing.
// Reading merges vertices with bit-identical coordinates, so the connectivity of a mesh
// written by any exporter that repeats vertex coordinates exactly is recovered.
#include <string>

#include "coupler_lib/geometry/triangle_mesh.hpp"

namespace lbdem {

// Throws ShapeError naming the file: missing, truncated, malformed, or no triangles.
TriangleMesh read_stl(const std::string& path);

void write_stl_ascii(const std::string& path, const TriangleMesh& mesh,
                     const std::string& solid_name = "shape");
void write_stl_binary(const std::string& path, const TriangleMesh& mesh);

}  // namespace lbdem
