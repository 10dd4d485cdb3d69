#include "coupler_lib/scene/bodies_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>

namespace lbdem {

namespace {

const std::vector<std::string> kColumns = {"x",  "y",  "z",  "qw", "qx", "qy",    "qz",     "vx",
                                           "vy", "vz", "wx", "wy", "wz", "shape", "density"};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// Where a bad value sits: the CSV file and line, plus the scene entry that named the file.
struct FileError {
  std::string file;
  std::string entry;
  [[noreturn]] void fail(long line, const std::string& what) const {
    throw SceneError(file + ":" + std::to_string(line) + ": " + what + " (bodies file of " + entry +
                     ")");
  }
};

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

// Columns that come as a group: all or none.
void require_group(const std::map<std::string, size_t>& col, const std::vector<std::string>& group,
                   const FileError& err, long header_line) {
  size_t present = 0;
  for (const auto& c : group) present += col.count(c);
  if (present != 0 && present != group.size()) {
    std::string names;
    for (const auto& c : group) names += (names.empty() ? "" : ", ") + c;
    err.fail(header_line, "columns " + names + " come together: all of them or none");
  }
}

}  // namespace

std::vector<BodyParams> read_bodies_file(Section& entry, const std::vector<ShapeParams>& shapes) {
  const auto name = entry.require<std::string>(
      "file", "CSV file of bodies (docs/study.md), relative to the scene");
  std::filesystem::path path(name);
  if (path.is_relative()) path = std::filesystem::path(entry.file()).parent_path() / path;
  std::ifstream in(path);
  if (!in) entry.fail("file", "cannot open '" + path.string() + "'");

  std::optional<int> entry_shape;
  if (entry.has("shape")) {
    const auto s = entry.require<std::string>("shape", "shape of every body of the file");
    const int k = shape_index(s, shapes);
    if (k < 0) entry.fail("shape", "no shape named '" + s + "' in the shapes catalogue");
    entry_shape = k;
  }
  std::optional<double> entry_density;
  if (entry.has("density"))
    entry_density = entry.require<double>("density", "density of every body of the file in kg/m^3",
                                          Bounds::positive());
  entry.finish();

  const FileError err{path.string(), entry.where("file")};
  std::map<std::string, size_t> col;
  long header_line = 0, lineno = 0;
  std::vector<BodyParams> out;
  std::string line;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto fields = split(t);
    if (header_line == 0) {
      header_line = lineno;
      for (size_t i = 0; i < fields.size(); ++i) {
        const auto& f = fields[i];
        bool known = false;
        for (const auto& c : kColumns) known = known || c == f;
        if (!known) {
          const auto hint = did_you_mean(f, kColumns);
          err.fail(lineno, "unknown column '" + f + "'" +
                               (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                               "; expected x, y, z and optionally qw qx qy qz, vx vy vz, wx wy wz, "
                               "shape, density");
        }
        if (!col.emplace(f, i).second) err.fail(lineno, "column '" + f + "' appears twice");
      }
      for (const char* c : {"x", "y", "z"})
        if (!col.count(c)) err.fail(lineno, std::string("missing column '") + c + "'");
      require_group(col, {"qw", "qx", "qy", "qz"}, err, lineno);
      require_group(col, {"vx", "vy", "vz"}, err, lineno);
      require_group(col, {"wx", "wy", "wz"}, err, lineno);
      if (col.count("shape") == static_cast<size_t>(entry_shape.has_value()))
        err.fail(lineno, entry_shape
                             ? "'shape' is both a column and a key of the entry; give one"
                             : "no 'shape': give a 'shape' column or the entry's 'shape' key");
      if (col.count("density") == static_cast<size_t>(entry_density.has_value()))
        err.fail(lineno,
                 entry_density
                     ? "'density' is both a column and a key of the entry; give one"
                     : "no 'density': give a 'density' column or the entry's 'density' key");
      continue;
    }
    if (fields.size() != col.size())
      err.fail(lineno, "expected " + std::to_string(col.size()) +
                           " comma-separated values (one per header column), got " +
                           std::to_string(fields.size()));
    auto number = [&](const char* c) {
      const auto& text = fields[col.at(c)];
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
        err.fail(lineno,
                 std::string("column '") + c + "': expected a finite number, got '" + text + "'");
      return v;
    };
    BodyParams b;
    b.position = {number("x"), number("y"), number("z")};
    if (col.count("qw")) {
      const std::array<double, 4> q{number("qw"), number("qx"), number("qy"), number("qz")};
      const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (!(n > 1e-12)) err.fail(lineno, "columns qw qx qy qz: the quaternion must not be zero");
      b.orientation = {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
    }
    if (col.count("vx")) b.velocity = {number("vx"), number("vy"), number("vz")};
    if (col.count("wx")) b.angular_velocity = {number("wx"), number("wy"), number("wz")};
    if (entry_shape) {
      b.shape = *entry_shape;
    } else {
      const auto& s = fields[col.at("shape")];
      b.shape = shape_index(s, shapes);
      if (b.shape < 0)
        err.fail(lineno, "column 'shape': no shape named '" + s +
                             "' in the shapes catalogue (have: " + shape_names(shapes) + ")");
    }
    b.density = entry_density ? *entry_density : number("density");
    if (!(b.density > 0))
      err.fail(lineno, "column 'density': expected a density > 0 in kg/m^3, got " +
                           fields[col.at("density")]);
    out.push_back(b);
  }
  if (header_line == 0) err.fail(lineno, "no header line (x,y,z,...) and no bodies");
  if (out.empty()) err.fail(lineno, "a header but no bodies");
  return out;
}

}  // namespace lbdem
