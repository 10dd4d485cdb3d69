// The surfaces the DEM output places at each body's pose (display_surface.hpp): in the shape
// frame, on the true shape's surface, enclosing its volume, for every kind a scene can name.
#include "coupler_lib/geometry/display_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/geometry/mass_properties.hpp"
#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/stl_io.hpp"
#include "temp_file.hpp"

namespace lbdem {
namespace {

ShapeParams params(const char* kind, double a, double b, double c) {
  ShapeParams p;
  p.kind = value_of(kShapeKindWords, kind);
  p.extents = {a, b, c};
  return p;
}

TEST(DisplaySurface, SphereVerticesLieOnTheSphere) {
  const TriangleMesh m = display_surface(params("sphere", 0.5, 0.5, 0.5), Eigen::Vector3d::Zero());
  EXPECT_EQ(m.triangles.size(), 320u);
  for (const auto& v : m.vertices) EXPECT_NEAR(v.norm(), 0.5, 1e-14);
  // Inscribed: a little below 4/3 pi r^3 (the level-2 icosphere holds 96.6 % of it).
  const double exact = 4.0 / 3.0 * std::numbers::pi * 0.125;
  EXPECT_GT(signed_volume(m), 0.95 * exact);
  EXPECT_LT(signed_volume(m), exact);
}

TEST(DisplaySurface, EllipsoidVerticesLieOnTheEllipsoid) {
  const TriangleMesh m = display_surface(params("ellipsoid", 1, 2, 3), Eigen::Vector3d::Zero());
  for (const auto& v : m.vertices)
    EXPECT_NEAR(std::pow(v.x() / 1, 2) + std::pow(v.y() / 2, 2) + std::pow(v.z() / 3, 2), 1, 1e-13);
  EXPECT_GT(signed_volume(m), 0);
}

TEST(DisplaySurface, CuboidIsItsTwelveTriangles) {
  const TriangleMesh m = display_surface(params("cuboid", 1, 2, 3), Eigen::Vector3d::Zero());
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(m), 6, 1e-13);
  const TriangleMesh c = display_surface(params("cube", 2, 2, 2), Eigen::Vector3d::Zero());
  EXPECT_NEAR(signed_volume(c), 8, 1e-13);
}

// An STL whose frame does not have the centroid at its origin: the surface is moved so that it
// does, as the body's position is its centroid.
TEST(DisplaySurface, StlIsTheFileMeshAboutItsCentroid) {
  TriangleMesh box = box_mesh(Eigen::Vector3d(1, 2, 3));
  transform_mesh(box, Eigen::Matrix3d::Identity(), Eigen::Vector3d(5, 6, 7));
  test::TempFile file("display_surface_box.stl");
  write_stl_binary(file.str(), box);
  ShapeParams p = params("stl", 1, 2, 3);
  p.file = file.str();
  p.scale = 2;
  const Eigen::Vector3d centroid = mass_properties(make_solid(p)).centroid;
  EXPECT_NEAR((centroid - Eigen::Vector3d(10, 12, 14)).norm(), 0, 1e-12);
  const TriangleMesh m = display_surface(p, centroid);
  Eigen::Vector3d lo, hi;
  bounding_box(m, lo, hi);
  EXPECT_NEAR((lo + Eigen::Vector3d(1, 2, 3)).norm(), 0, 1e-12);
  EXPECT_NEAR((hi - Eigen::Vector3d(1, 2, 3)).norm(), 0, 1e-12);
  EXPECT_NEAR(signed_volume(m), 48, 1e-11);
}

TEST(DisplaySurface, OneSurfacePerShapeOfTheCatalogue) {
  Shape cube;
  EXPECT_EQ(display_surfaces({params("cube", 1, 1, 1)}, {cube}).size(), 1u);
  EXPECT_THROW(display_surfaces({params("cube", 1, 1, 1)}, {}), std::logic_error);
}

}  // namespace
}  // namespace lbdem
