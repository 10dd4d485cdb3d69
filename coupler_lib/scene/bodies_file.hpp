#pragma once
// Bodies read from a CSV file (`bodies: [{file: packing.csv, shape: cube, density: 2500}]`), as
// written by tools/lbdem/packing.py or by any other tool. One row per body; the header names the
// columns, in any order:
//   x, y, z          centre of mass in m (required)
//   qw, qx, qy, qz   orientation, shape frame -> space (all four or none; default 1 0 0 0)
//   vx, vy, vz       velocity in m/s (all three or none; default 0)
//   wx, wy, wz       angular velocity in rad/s (all three or none; default 0)
//   shape, density   shape name in the catalogue, kg/m^3: each either a column or a key
//                    of the entry, never both
// Lines starting with '#' and blank lines are skipped. Every value is checked as an inline body
// is (the overlap and in-box checks of the DEM setup then apply to all bodies alike); a bad file
// stops the parse with `file:line: column: what was expected`.
#include <vector>

#include "coupler_lib/scene/bodies_section.hpp"

namespace lbdem {

// Reads the bodies of one `file:` entry of the `bodies:` list (docs/study.md, "Bodies from a
// file").
std::vector<BodyParams> read_bodies_file(Section& entry, const std::vector<ShapeParams>& shapes);

}  // namespace lbdem
