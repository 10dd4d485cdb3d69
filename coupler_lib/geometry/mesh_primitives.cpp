#include "coupler_lib/geometry/mesh_primitives.hpp"

#include <cmath>
#include <map>
#include <numbers>

namespace lbdem {

namespace {

// Reverse every triangle when the mesh came out inside out.
void orient_outward(TriangleMesh& m) {
  if (signed_volume(m) < 0)
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
}

}  // namespace

TriangleMesh box_mesh(const Eigen::Vector3d& edges) {
  TriangleMesh m;
  const Eigen::Vector3d h = edges / 2;
  for (int k = 0; k < 8; ++k)  // vertex k has bit d set when it lies on the + side along d
    m.vertices.emplace_back((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(),
                            (k & 4) ? h.z() : -h.z());
  // Each face as a quad (a, b, c, d) counter-clockwise from outside, split along a-c.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  orient_outward(m);
  return m;
}

TriangleMesh torus_mesh(double ring, double tube, int around, int across) {
  TriangleMesh m;
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const double u = 2 * std::numbers::pi * i / around, v = 2 * std::numbers::pi * j / across;
      const double rho = ring + tube * std::cos(v);
      m.vertices.emplace_back(rho * std::cos(u), rho * std::sin(u), tube * std::sin(v));
    }
  const auto id = [&](int i, int j) { return (i % around) * across + j % across; };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  orient_outward(m);
  return m;
}

TriangleMesh icosphere_mesh(double radius, int levels) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;  // golden ratio
  TriangleMesh m;
  const double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : v) m.vertices.push_back(Eigen::Vector3d(p[0], p[1], p[2]).normalized());
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      const int id = static_cast<int>(m.vertices.size()) - 1;
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(m.triangles.size() * 4);
    for (const auto& tri : m.triangles) {
      const int a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    m.triangles.swap(next);
  }
  for (auto& p : m.vertices) p *= radius;
  orient_outward(m);
  return m;
}

TriangleMesh octahedron_mesh(double a) {
  TriangleMesh m;
  m.vertices = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}};
  // One triangle per octant, counter-clockwise seen from outside.
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) {
        std::array<int, 3> tri{sx, sy, sz};
        const int flips = (sx == 1) + (sy == 3) + (sz == 5);
        if (flips % 2 == 1) std::swap(tri[1], tri[2]);
        m.triangles.push_back(tri);
      }
  return m;
}

void transform_mesh(TriangleMesh& mesh, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  for (auto& p : mesh.vertices) p = R * p + t;
}

}  // namespace lbdem
