#pragma once
// Bodies read from a file (`bodies: [{file: packing.csv, shape: cube, density: 2500}]`), as
// written by tools/lbdem/packing.py or by any other tool, in one of two formats: CSV or HDF5,
// chosen by the entry's `format` key (csv | hdf5), by default from the extension (.h5 and .hdf5:
// HDF5, anything else: CSV). Both give the same fields (docs/study.md, "Bodies from a file"):
//   position           centre of mass in m (required)
//   orientation        quaternion w, x, y, z, shape frame -> space (default 1 0 0 0; normalised)
//   velocity           m/s (default 0)
//   angular_velocity   rad/s (default 0)
//   shape, density     shape name in the catalogue, kg/m^3: each either in the file or a key of
//                      the entry, never both
// CSV: one row per body; the header names the columns, in any order: x, y, z; qw, qx, qy, qz;
// vx, vy, vz; wx, wy, wz (each group all or none); shape; density. Lines starting with '#' and
// blank lines are skipped.
// HDF5: one dataset per field at the root of the file, one row per body: position (N x 3),
// orientation (N x 4), velocity (N x 3), angular_velocity (N x 3), density (N), shape (N
// strings, fixed or variable length); numbers of any integer or floating type.
// Every value is checked as an inline body is (the overlap and in-box checks then apply to all
// bodies alike); a bad file stops the parse naming the file, the line (CSV) or body index (HDF5),
// the column or dataset and what was expected, and the scene entry that named the file.
#include <vector>

#include "coupler_lib/scene/bodies_section.hpp"

namespace lbdem {

// Reads the bodies of one `file:` entry of the `bodies:` list.
// The keys of a `bodies:` entry that names a file (its alternative in body_schema()).
std::vector<KeySchema> bodies_file_keys();
std::vector<BodyParams> read_bodies_file(Section& entry, const std::vector<ShapeParams>& shapes);

}  // namespace lbdem
