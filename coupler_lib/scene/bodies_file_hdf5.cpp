// Bodies files in HDF5 (bodies_file.hpp): one dataset per field at the root, one row per body.
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include "coupler_lib/output/hdf5_read.hpp"
#include "coupler_lib/scene/bodies_file_format.hpp"

namespace lbdem {

namespace {

// Dataset name -> values per body (0: one value, a 1-D dataset of strings or numbers).
const std::map<std::string, size_t> kDatasets = {{"position", 3}, {"orientation", 4},
                                                 {"velocity", 3}, {"angular_velocity", 3},
                                                 {"density", 0},  {"shape", 0}};

const FieldNames kNames{"dataset", "dataset 'orientation'", "dataset 'shape'", "dataset 'density'"};

std::string at_body(size_t i) {
  std::string s(": body ");  // appended: see at_line in bodies_file_csv.cpp
  s += std::to_string(i);
  return s;
}

std::string dims_text(const std::vector<size_t>& dims) {
  if (dims.empty()) return "a scalar";
  std::string s;
  for (size_t d : dims) s += (s.empty() ? "" : " x ") + std::to_string(d);
  return s;
}

// The shape of every dataset: N x width numbers (N numbers, N strings for shape); N the same for
// all, taken from position.
void check_layout(const std::map<std::string, const H5Array*>& sets, const BodiesFileEntry& e) {
  const auto pos = sets.find("position");
  if (pos == sets.end())
    fail_bodies_file(e, "", "missing dataset 'position' (N x 3 centres of mass in m)");
  if (pos->second->dims.empty() || pos->second->dims[0] == 0)
    fail_bodies_file(e, "", "dataset 'position' has no bodies");
  const size_t n = pos->second->dims[0];
  for (const auto& [name, a] : sets) {
    const size_t width = kDatasets.at(name);
    const bool text = name == "shape";
    const std::vector<size_t> want = width ? std::vector<size_t>{n, width} : std::vector<size_t>{n};
    if (a->dims != want || a->text != text)
      fail_bodies_file(e, "",
                       "dataset '" + name + "': expected " + dims_text(want) +
                           (text ? " strings" : " numbers") +
                           " (one row per body, as many as "
                           "'position' has), got " +
                           dims_text(a->dims) + (a->text ? " strings" : " numbers"));
  }
}

}  // namespace

std::vector<BodyParams> read_bodies_hdf5(const BodiesFileEntry& e,
                                         const std::vector<ShapeParams>& shapes) {
  std::vector<H5Array> arrays;
  try {
    arrays = read_root_datasets(e.path);
  } catch (const std::runtime_error& err) {
    throw SceneError(std::string(err.what()) + " (bodies file of " + e.where + ")");
  }
  std::map<std::string, const H5Array*> sets;
  std::vector<std::string> known;
  for (const auto& [name, width] : kDatasets) known.push_back(name);
  for (const auto& a : arrays) {
    if (!kDatasets.count(a.name)) {
      const auto hint = did_you_mean(a.name, known);
      fail_bodies_file(e, "",
                       "unknown dataset '" + a.name + "'" +
                           (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                           "; expected position and optionally orientation, velocity, "
                           "angular_velocity, shape, density");
    }
    sets[a.name] = &a;
  }
  check_layout(sets, e);
  check_shape_and_density_source(e, sets.count("shape") > 0, sets.count("density") > 0, kNames, "");

  auto row = [&](const char* name, size_t i, size_t width) {
    const auto it = sets.find(name);
    const double* v = it->second->numbers.data() + i * width;
    for (size_t k = 0; k < width; ++k)
      if (!std::isfinite(v[k]))
        fail_bodies_file(e, at_body(i),
                         std::string("dataset '") + name + "': expected finite numbers, got " +
                             std::to_string(v[k]));
    return v;
  };
  const size_t n = sets.at("position")->dims[0];
  std::vector<BodyParams> out;
  out.reserve(n);
  for (size_t i = 0; i < n; ++i) {
    FileBody raw;
    const double* p = row("position", i, 3);
    raw.position = {p[0], p[1], p[2]};
    if (sets.count("orientation")) {
      const double* q = row("orientation", i, 4);
      raw.orientation = std::array<double, 4>{q[0], q[1], q[2], q[3]};
    }
    if (sets.count("velocity")) {
      const double* v = row("velocity", i, 3);
      raw.velocity = std::array<double, 3>{v[0], v[1], v[2]};
    }
    if (sets.count("angular_velocity")) {
      const double* w = row("angular_velocity", i, 3);
      raw.angular_velocity = std::array<double, 3>{w[0], w[1], w[2]};
    }
    if (sets.count("shape")) raw.shape = sets.at("shape")->strings[i];
    if (sets.count("density")) raw.density = *row("density", i, 1);
    out.push_back(checked_body(raw, e, shapes, kNames, at_body(i)));
  }
  return out;
}

}  // namespace lbdem
