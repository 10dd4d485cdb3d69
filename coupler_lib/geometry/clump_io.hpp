#pragma once
// Clump files: plain text, one sphere per line "x y z r" (shape frame, metres before
// scaling), '#' starts a comment line. clump_gen writes a header of comments giving the
// shape, the method, its parameters and the measured shape errors.
#include <string>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"

namespace lbdem {

// Multiplies coordinates and radii by `scale`. Throws ShapeError naming file and line.
Clump read_clump(const std::string& path, double scale = 1.0);

// `header` lines are written as comments ("# " prepended).
void write_clump(const std::string& path, const Clump& clump,
                 const std::vector<std::string>& header);

}  // namespace lbdem
