// Bodies files in CSV (bodies_file.hpp): a header naming the columns, one row per body.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "coupler_lib/scene/bodies_file_format.hpp"

namespace lbdem {

namespace {

const std::vector<std::string> kColumns = {"x",  "y",  "z",  "qw", "qx", "qy",    "qz",     "vx",
                                           "vy", "vz", "wx", "wy", "wz", "shape", "density"};

const FieldNames kNames{"column", "columns qw qx qy qz", "column 'shape'", "column 'density'"};

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

std::string at_line(long line) {
  std::string s(":");  // appended, not ":" + std::string: GCC 12 warns (-Wrestrict) on that
  s += std::to_string(line);
  return s;
}

// Columns that come as a group: all or none.
void require_group(const std::map<std::string, size_t>& col, const std::vector<std::string>& group,
                   const BodiesFileEntry& e, long header_line) {
  size_t present = 0;
  for (const auto& c : group) present += col.count(c);
  if (present != 0 && present != group.size()) {
    std::string names;
    for (const auto& c : group) names += (names.empty() ? "" : ", ") + c;
    fail_bodies_file(e, at_line(header_line),
                     "columns " + names + " come together: all of them or none");
  }
}

// The header line: known columns, each once, x y z present, groups complete.
std::map<std::string, size_t> read_header(const std::vector<std::string>& fields,
                                          const BodiesFileEntry& e, long lineno) {
  std::map<std::string, size_t> col;
  for (size_t i = 0; i < fields.size(); ++i) {
    const auto& f = fields[i];
    bool known = false;
    for (const auto& c : kColumns) known = known || c == f;
    if (!known) {
      const auto hint = did_you_mean(f, kColumns);
      fail_bodies_file(e, at_line(lineno),
                       "unknown column '" + f + "'" +
                           (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                           "; expected x, y, z and optionally qw qx qy qz, vx vy vz, wx wy wz, "
                           "shape, density");
    }
    if (!col.emplace(f, i).second)
      fail_bodies_file(e, at_line(lineno), "column '" + f + "' appears twice");
  }
  for (const char* c : {"x", "y", "z"})
    if (!col.count(c))
      fail_bodies_file(e, at_line(lineno), std::string("missing column '") + c + "'");
  require_group(col, {"qw", "qx", "qy", "qz"}, e, lineno);
  require_group(col, {"vx", "vy", "vz"}, e, lineno);
  require_group(col, {"wx", "wy", "wz"}, e, lineno);
  check_shape_and_density_source(e, col.count("shape") > 0, col.count("density") > 0, kNames,
                                 at_line(lineno));
  return col;
}

}  // namespace

std::vector<BodyParams> read_bodies_csv(const BodiesFileEntry& e,
                                        const std::vector<ShapeParams>& shapes) {
  std::ifstream in(e.path);
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
      col = read_header(fields, e, lineno);
      continue;
    }
    if (fields.size() != col.size())
      fail_bodies_file(e, at_line(lineno),
                       "expected " + std::to_string(col.size()) +
                           " comma-separated values (one per header column), got " +
                           std::to_string(fields.size()));
    auto number = [&](const char* c) {
      const auto& text = fields[col.at(c)];
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v))
        fail_bodies_file(
            e, at_line(lineno),
            std::string("column '") + c + "': expected a finite number, got '" + text + "'");
      return v;
    };
    FileBody raw;
    raw.position = {number("x"), number("y"), number("z")};
    if (col.count("qw"))
      raw.orientation =
          std::array<double, 4>{number("qw"), number("qx"), number("qy"), number("qz")};
    if (col.count("vx"))
      raw.velocity = std::array<double, 3>{number("vx"), number("vy"), number("vz")};
    if (col.count("wx"))
      raw.angular_velocity = std::array<double, 3>{number("wx"), number("wy"), number("wz")};
    if (col.count("shape")) raw.shape = fields[col.at("shape")];
    if (col.count("density")) raw.density = number("density");
    out.push_back(checked_body(raw, e, shapes, kNames, at_line(lineno)));
  }
  if (header_line == 0)
    fail_bodies_file(e, at_line(lineno), "no header line (x,y,z,...) and no bodies");
  if (out.empty()) fail_bodies_file(e, at_line(lineno), "a header but no bodies");
  return out;
}

}  // namespace lbdem
