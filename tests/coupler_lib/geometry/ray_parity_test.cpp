// The crossing test behind mesh inside/outside: a vertical line through a vertex must cross
// the closed surface an even number of times, whatever the compiler does with the side tests.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "coupler_lib/geometry/ray_parity.hpp"
#include "coupler_lib/geometry/stl_io.hpp"
#include "temp_file.hpp"

namespace lbdem {
namespace {

// A torus (ring 0.5 mm, tube 0.2 mm, 48 x 24 segments) written as an ASCII STL with 12
// significant digits, as a script would write it: its vertices at 120 and 240 degrees around
// the tube in the plane y = 0 lie exactly above one another at x = 0.0004. The line through
// them crossed the surface 3 times when the side test a * b - c * d was fused into a
// multiply-add (-march=native); it must cross twice.
TEST(RayParity, LineThroughStackedVerticesCrossesTwice) {
  const int around = 48, across = 24;
  const auto point = [&](int i, int j) {
    const double u = 2 * std::numbers::pi * (i % around) / around;
    const double v = 2 * std::numbers::pi * (j % across) / across;
    const double rho = 0.5e-3 + 0.2e-3 * std::cos(v);
    return Eigen::Vector3d(rho * std::cos(u), rho * std::sin(u), 0.2e-3 * std::sin(v));
  };
  const test::TempFile file("torus_12_digits.stl");
  {
    std::FILE* f = std::fopen(file.str().c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f, "solid t\n");
    for (int i = 0; i < around; ++i)
      for (int j = 0; j < across; ++j) {
        const Eigen::Vector3d tris[2][3] = {{point(i, j), point(i + 1, j), point(i + 1, j + 1)},
                                            {point(i, j), point(i + 1, j + 1), point(i, j + 1)}};
        for (const auto& t : tris) {
          std::fprintf(f, " facet normal 0 0 0\n  outer loop\n");
          for (const auto& p : t)
            std::fprintf(f, "   vertex %.12g %.12g %.12g\n", p.x(), p.y(), p.z());
          std::fprintf(f, "  endloop\n endfacet\n");
        }
      }
    std::fprintf(f, "endsolid t\n");
    std::fclose(f);
  }
  const TriangleMesh m = read_stl(file.str());
  const auto crossings = [&](double x, double y) {
    int n = 0;
    for (const auto& t : m.triangles) {
      double z;
      if (pierces_column(t, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], x, y, z)) ++n;
    }
    return n;
  };
  EXPECT_EQ(crossings(0.0004, 0.0), 2);
  // At 90 degrees the vertices sit at x = 2.4e-20 (cos(pi / 2) rounded): this line 4e-21 off
  // them, closer than the side tests' round-off, crossed 3 times with a floating-point test;
  // the exact one (orientation) sees where it really is.
  EXPECT_EQ(crossings(2.0328790734103208e-20, 0.0004), 2);
}

}  // namespace
}  // namespace lbdem
