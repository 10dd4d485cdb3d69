#pragma once
// What the two bodies-file formats (bodies_file_csv.cpp, bodies_file_hdf5.cpp) share: the entry
// that names the file, the error style, and the checks of one body's values, so that a CSV file
// and an HDF5 file are validated by the same code (bodies_file.hpp).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/scene/bodies_section.hpp"

namespace lbdem {

// The `file:` entry of the bodies list, resolved.
struct BodiesFileEntry {
  std::string path;               // the file, resolved against the scene's folder
  std::optional<int> shape;       // the entry's `shape` key, as a catalogue index
  std::optional<double> density;  // the entry's `density` key
  std::string where;              // "scene.yaml:12: bodies[0].file", for messages
};

// Throws SceneError "<file><location>: <what> (bodies file of <entry>)"; location is ":12" (a CSV
// line), ": body 3" (an HDF5 row) or "" (the whole file).
[[noreturn]] void fail_bodies_file(const BodiesFileEntry& e, const std::string& location,
                                   const std::string& what);

// How a format names a field in messages.
struct FieldNames {
  std::string kind;         // "column" or "dataset"
  std::string orientation;  // "columns qw qx qy qz", "dataset 'orientation'"
  std::string shape;        // "column 'shape'", "dataset 'shape'"
  std::string density;      // "column 'density'", "dataset 'density'"
};

// Shape and density come once each: from the file (has_shape, has_density) or from the entry.
void check_shape_and_density_source(const BodiesFileEntry& e, bool has_shape, bool has_density,
                                    const FieldNames& names, const std::string& location);

// One body as a file gives it, before the checks.
struct FileBody {
  std::array<double, 3> position{};
  std::optional<std::array<double, 4>> orientation;
  std::optional<std::array<double, 3>> velocity;
  std::optional<std::array<double, 3>> angular_velocity;
  std::optional<std::string> shape;  // a name, when the file has the field
  std::optional<double> density;     // when the file has the field
};

// The body with its quaternion normalised, its shape looked up and its density checked.
BodyParams checked_body(const FileBody& raw, const BodiesFileEntry& e,
                        const std::vector<ShapeParams>& shapes, const FieldNames& names,
                        const std::string& location);

std::vector<BodyParams> read_bodies_csv(const BodiesFileEntry& e,
                                        const std::vector<ShapeParams>& shapes);
std::vector<BodyParams> read_bodies_hdf5(const BodiesFileEntry& e,
                                         const std::vector<ShapeParams>& shapes);

}  // namespace lbdem
