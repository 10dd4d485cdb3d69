#include "coupler_lib/geometry/stl_io.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "coupler_lib/errors.hpp"

namespace lbdem {

namespace {

// Merges vertices with identical coordinates into one index.
class VertexPool {
 public:
  explicit VertexPool(TriangleMesh& mesh) : mesh_(mesh) {}
  int add(const Eigen::Vector3d& p) {
    const auto [it, fresh] =
        index_.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(mesh_.vertices.size()));
    if (fresh) mesh_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& mesh_;
  std::map<std::array<double, 3>, int> index_;
};

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ShapeError(path + ": cannot open the STL file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::uint32_t le_u32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return std::uint32_t(u[0]) | std::uint32_t(u[1]) << 8 | std::uint32_t(u[2]) << 16 |
         std::uint32_t(u[3]) << 24;
}

float le_f32(const char* p) {
  const std::uint32_t u = le_u32(p);
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

void put_u32(std::ostream& out, std::uint32_t v) {
  const char b[4] = {char(v & 0xff), char((v >> 8) & 0xff), char((v >> 16) & 0xff),
                     char((v >> 24) & 0xff)};
  out.write(b, 4);
}

void put_f32(std::ostream& out, float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  put_u32(out, u);
}

TriangleMesh parse_binary(const std::string& path, const std::string& data) {
  const std::uint32_t n = le_u32(data.data() + 80);
  TriangleMesh mesh;
  VertexPool pool(mesh);
  mesh.triangles.reserve(n);
  for (std::uint32_t t = 0; t < n; ++t) {
    const char* rec = data.data() + 84 + 50 * std::size_t(t) + 12;  // skip the normal
    std::array<int, 3> tri{};
    for (int v = 0; v < 3; ++v) {
      const Eigen::Vector3d p(le_f32(rec + 12 * v), le_f32(rec + 12 * v + 4),
                              le_f32(rec + 12 * v + 8));
      if (!p.allFinite())
        throw ShapeError(path + ": triangle " + std::to_string(t) + " has a non-finite vertex");
      tri[v] = pool.add(p);
    }
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

TriangleMesh parse_ascii(const std::string& path, const std::string& data) {
  TriangleMesh mesh;
  VertexPool pool(mesh);
  std::istringstream in(data);
  std::string line;
  int line_no = 0;
  std::array<int, 3> tri{};
  int nv = -1;  // vertices read in the current loop; -1 outside a facet
  auto fail = [&](const std::string& what) {
    throw ShapeError(path + ":" + std::to_string(line_no) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    std::istringstream ls(line);
    std::string word;
    if (!(ls >> word)) continue;
    if (word == "facet") {
      if (nv >= 0) fail("'facet' inside another facet");
      nv = 0;
    } else if (word == "vertex") {
      if (nv < 0) fail("'vertex' outside a facet");
      if (nv >= 3) fail("more than 3 vertices in a facet");
      double x, y, z;
      if (!(ls >> x >> y >> z)) fail("expected 'vertex x y z'");
      tri[nv++] = pool.add({x, y, z});
    } else if (word == "endfacet") {
      if (nv != 3) fail("facet with " + std::to_string(std::max(nv, 0)) + " vertices, expected 3");
      mesh.triangles.push_back(tri);
      nv = -1;
    } else if (word != "solid" && word != "endsolid" && word != "outer" && word != "endloop") {
      fail("unexpected '" + word + "' in an ASCII STL");
    }
  }
  if (nv >= 0) fail("file ends inside a facet");
  return mesh;
}

}  // namespace

TriangleMesh read_stl(const std::string& path) {
  const std::string data = read_all(path);
  // Binary STL: 80-byte header, uint32 count, 50 bytes per triangle. Trust the size match
  // over the "solid" prefix: some binary exporters start their header with "solid".
  const bool binary =
      data.size() >= 84 && data.size() == 84 + 50 * std::size_t(le_u32(data.data() + 80));
  TriangleMesh mesh;
  if (binary) {
    mesh = parse_binary(path, data);
  } else if (data.compare(0, 5, "solid") == 0) {
    mesh = parse_ascii(path, data);
  } else {
    throw ShapeError(path + ": not an STL file (no 'solid' keyword, and the size " +
                     std::to_string(data.size()) +
                     " bytes does not match a binary STL's triangle count)");
  }
  if (mesh.triangles.empty()) throw ShapeError(path + ": the STL file has no triangles");
  return mesh;
}

void write_stl_ascii(const std::string& path, const TriangleMesh& mesh,
                     const std::string& solid_name) {
  std::ofstream out(path);
  if (!out) throw ShapeError(path + ": cannot write the STL file");
  out.precision(17);
  out << "solid " << solid_name << "\n";
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    const auto& b = mesh.vertices[t[1]];
    const auto& c = mesh.vertices[t[2]];
    const Eigen::Vector3d nrm = (b - a).cross(c - a).normalized();
    out << "  facet normal " << nrm.x() << " " << nrm.y() << " " << nrm.z() << "\n"
        << "    outer loop\n";
    for (const auto* p : {&a, &b, &c})
      out << "      vertex " << p->x() << " " << p->y() << " " << p->z() << "\n";
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid " << solid_name << "\n";
  if (!out) throw ShapeError(path + ": error while writing the STL file");
}

void write_stl_binary(const std::string& path, const TriangleMesh& mesh) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw ShapeError(path + ": cannot write the STL file");
  char header[80] = {};
  std::strncpy(header, "binary STL written by lbdem", sizeof header - 1);
  out.write(header, 80);
  put_u32(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    const auto& b = mesh.vertices[t[1]];
    const auto& c = mesh.vertices[t[2]];
    const Eigen::Vector3d nrm = (b - a).cross(c - a).normalized();
    for (int i = 0; i < 3; ++i) put_f32(out, static_cast<float>(nrm[i]));
    for (const auto* p : {&a, &b, &c})
      for (int i = 0; i < 3; ++i) put_f32(out, static_cast<float>((*p)[i]));
    out.write("\0\0", 2);
  }
  if (!out) throw ShapeError(path + ": error while writing the STL file");
}

}  // namespace lbdem
