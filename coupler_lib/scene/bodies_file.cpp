#include "coupler_lib/scene/bodies_file.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "coupler_lib/scene/bodies_file_format.hpp"

namespace lbdem {

namespace {

int shape_index(const std::string& name, const std::vector<ShapeParams>& shapes) {
  for (size_t i = 0; i < shapes.size(); ++i)
    if (shapes[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string shape_names(const std::vector<ShapeParams>& shapes) {
  std::string out;
  for (const auto& s : shapes) out += (out.empty() ? "" : ", ") + s.name;
  return out;
}

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

void fail_bodies_file(const BodiesFileEntry& e, const std::string& location,
                      const std::string& what) {
  throw SceneError(e.path + location + ": " + what + " (bodies file of " + e.where + ")");
}

void check_shape_and_density_source(const BodiesFileEntry& e, bool has_shape, bool has_density,
                                    const FieldNames& names, const std::string& location) {
  if (has_shape == e.shape.has_value())
    fail_bodies_file(
        e, location,
        e.shape ? "'shape' is both a " + names.kind + " and a key of the entry; give one"
                : "no 'shape': give a 'shape' " + names.kind + " or the entry's 'shape' key");
  if (has_density == e.density.has_value())
    fail_bodies_file(
        e, location,
        e.density
            ? "'density' is both a " + names.kind + " and a key of the entry; give one"
            : "no 'density': give a 'density' " + names.kind + " or the entry's 'density' key");
}

BodyParams checked_body(const FileBody& raw, const BodiesFileEntry& e,
                        const std::vector<ShapeParams>& shapes, const FieldNames& names,
                        const std::string& location) {
  BodyParams b;
  b.position = raw.position;
  if (raw.orientation) {
    const auto& q = *raw.orientation;
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(n > 1e-12))
      fail_bodies_file(e, location, names.orientation + ": the quaternion must not be zero");
    b.orientation = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
  }
  if (raw.velocity) b.velocity = *raw.velocity;
  if (raw.angular_velocity) b.angular_velocity = *raw.angular_velocity;
  if (e.shape) {
    b.shape = *e.shape;
  } else {
    b.shape = shape_index(*raw.shape, shapes);
    if (b.shape < 0)
      fail_bodies_file(e, location,
                       names.shape + ": no shape named '" + *raw.shape +
                           "' in the shapes catalogue (have: " + shape_names(shapes) + ")");
  }
  b.density = e.density ? *e.density : *raw.density;
  if (!(b.density > 0))
    fail_bodies_file(
        e, location,
        names.density + ": expected a density > 0 in kg/m^3, got " + number_text(b.density));
  return b;
}

std::vector<KeySchema> bodies_file_keys() {
  return {key::text("file", "bodies file, CSV or HDF5 (docs/study.md), relative to the scene")
              .required(),
          key::choice("format", words_of(kBodiesFormatWords),
                      "format of the bodies file (default: hdf5 for .h5 and .hdf5, else csv)")
              .derived_as("hdf5 for a file ending in .h5 or .hdf5, else csv"),
          key::text("shape", "shape of every body of the file")
              .absent_means("each body's shape is a column of the file"),
          key::number("density", "density of every body of the file in kg/m^3")
              .absent_means("each body's density is a column of the file")
              .within(Bounds::positive())
              .in("kg/m^3")};
}

std::vector<BodyParams> read_bodies_file(Section& entry, const std::vector<ShapeParams>& shapes) {
  const auto name = entry.require<std::string>("file");
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(entry.file()).parent_path() / path;
  const std::string ext = path.extension().string();
  const BodiesFormat format = value_of(
      kBodiesFormatWords, entry.choice("format", ext == ".h5" || ext == ".hdf5" ? "hdf5" : "csv"));
  if (!std::ifstream(path)) entry.fail("file", "cannot open '" + path.string() + "'");

  BodiesFileEntry e;
  e.path = path.string();
  if (entry.has("shape")) {
    const auto s = entry.require<std::string>("shape");
    const int k = shape_index(s, shapes);
    if (k < 0) entry.fail("shape", "no shape named '" + s + "' in the shapes catalogue");
    e.shape = k;
  }
  if (entry.has("density")) e.density = entry.require<double>("density");
  entry.finish();
  e.where = entry.where("file");
  return format == BodiesFormat::hdf5 ? read_bodies_hdf5(e, shapes) : read_bodies_csv(e, shapes);
}

}  // namespace lbdem
