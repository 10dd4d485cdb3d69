#include "coupler_lib/geometry/clump_io.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "coupler_lib/errors.hpp"

namespace lbdem {

Clump read_clump(const std::string& path, double scale) {
  std::ifstream in(path);
  if (!in) throw ShapeError(path + ": cannot open the clump file");
  Clump c;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ls(line);
    double x, y, z, r;
    std::string extra;
    if (!(ls >> x >> y >> z >> r) || (ls >> extra))
      throw ShapeError(path + ":" + std::to_string(line_no) +
                       ": expected 'x y z r' (four numbers), got '" + line + "'");
    if (!(r > 0) || !std::isfinite(x + y + z + r))
      throw ShapeError(path + ":" + std::to_string(line_no) +
                       ": sphere radius must be positive and coordinates finite");
    c.centers.emplace_back(x * scale, y * scale, z * scale);
    c.radii.push_back(r * scale);
  }
  if (c.radii.empty()) throw ShapeError(path + ": the clump file has no spheres");
  return c;
}

void write_clump(const std::string& path, const Clump& clump,
                 const std::vector<std::string>& header) {
  std::ofstream out(path);
  if (!out) throw ShapeError(path + ": cannot write the clump file");
  for (const auto& h : header) out << "# " << h << "\n";
  out << "# x y z r  (shape frame: centroid at the origin)\n";
  out.precision(10);
  for (std::size_t i = 0; i < clump.size(); ++i)
    out << clump.centers[i].x() << " " << clump.centers[i].y() << " " << clump.centers[i].z() << " "
        << clump.radii[i] << "\n";
  if (!out) throw ShapeError(path + ": error while writing the clump file");
}

}  // namespace lbdem
