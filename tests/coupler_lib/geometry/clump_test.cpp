// Clump generators (sphere counts, shape error decreasing with more spheres) and the clump
// file round trip.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/clump_generator.hpp"
#include "coupler_lib/geometry/clump_io.hpp"
#include "coupler_lib/geometry/mesh_check.hpp"
#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/voxelize.hpp"
#include "temp_file.hpp"

namespace lbdem {
namespace {

const SolidGeometry kCube = SolidGeometry::cuboid({1, 1, 1});

// Every sphere stays inside the solid (up to round-off): radius <= depth of its centre.
void expect_inscribed(const SolidGeometry& solid, const Clump& c) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    ASSERT_TRUE(solid.inside(c.centers[i]) || solid.distance_to_surface(c.centers[i]) < 1e-12);
    EXPECT_LE(c.radii[i], solid.distance_to_surface(c.centers[i]) + 1e-12);
  }
}

TEST(SurfaceClump, CubeCountsAreTheFaceGridPointsPlusACentreSphere) {
  const Voxels v = voxelize(kCube, 1.0 / 41);
  // n^3 - (n-2)^3 grid points lie on the faces of an n^3 grid; +1 centre sphere.
  for (int n : {3, 5, 10, 20}) {
    const Clump c = surface_clump(kCube, v, {n, 1.0, true});
    const std::size_t expected = n * n * n - (n - 2) * (n - 2) * (n - 2) + 1;
    EXPECT_EQ(c.size(), expected) << "grid " << n;
    expect_inscribed(kCube, c);
  }
  EXPECT_EQ(surface_clump(kCube, v, {10, 1.0, true}).size(), 489u);
  EXPECT_EQ(surface_clump(kCube, v, {20, 1.0, true}).size(), 2169u);
  EXPECT_EQ(surface_clump(kCube, v, {10, 1.0, false}).size(), 488u);
}

TEST(SurfaceClump, SpheresTouchTheCubeFaces) {
  const Voxels v = voxelize(kCube, 1.0 / 41);
  const Clump c = surface_clump(kCube, v, {10, 1.0, true});
  const double r = 1.0 / 11;  // s = L / (n - 1 + 2 ratio), r = ratio s
  double reach = 0;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    EXPECT_NEAR(c.radii[i], r, 1e-14);
    reach = std::max(reach, c.centers[i].cwiseAbs().maxCoeff() + c.radii[i]);
  }
  EXPECT_NEAR(reach, 0.5, 1e-12);
  EXPECT_NEAR(c.radii.back(), 0.5, 1e-12);  // centre sphere: the inscribed sphere
  EXPECT_LT(c.centers.back().norm(), 1e-12);
}

TEST(SurfaceClump, ShapeErrorDecreasesWithMoreSpheres) {
  const Voxels v = voxelize(kCube, 1.0 / 61);
  double prev_vol = 1e9, prev_dev = 1e9;
  for (int n : {3, 5, 10, 20}) {
    const Clump c = surface_clump(kCube, v, {n, 1.0, true});
    const ClumpQuality q = clump_quality(c, v);
    std::printf("cube surface grid %2d: %4zu spheres, volume error %.4f, max deviation %.4f\n", n,
                c.size(), q.volume_error, q.max_deviation);
    EXPECT_LT(q.volume_error, prev_vol);
    EXPECT_LT(q.max_deviation, prev_dev);
    prev_vol = q.volume_error;
    prev_dev = q.max_deviation;
  }
}

TEST(SurfaceClump, EllipsoidSpheresAreInscribedAndErrorsShrink) {
  const SolidGeometry egg = SolidGeometry::ellipsoid({0.5, 0.3, 0.2});
  const Voxels v = voxelize(egg, 1.0 / 50);
  const Clump coarse = surface_clump(egg, v, {8, 1.0, true});
  const Clump fine = surface_clump(egg, v, {16, 1.0, true});
  expect_inscribed(egg, coarse);
  expect_inscribed(egg, fine);
  const ClumpQuality qc = clump_quality(coarse, v), qf = clump_quality(fine, v);
  std::printf(
      "ellipsoid surface grid 8: %zu spheres, %.4f / %.4f; grid 16: %zu spheres, "
      "%.4f / %.4f (volume error / deviation)\n",
      coarse.size(), qc.volume_error, qc.max_deviation, fine.size(), qf.volume_error,
      qf.max_deviation);
  EXPECT_LT(qf.volume_error, qc.volume_error);
  EXPECT_LT(qf.max_deviation, qc.max_deviation);
}

TEST(FillClump, ReachesTheTargetCountWithInscribedSpheres) {
  const Voxels v = voxelize(kCube, 1.0 / 41);
  for (int n : {1, 27, 100}) {
    const Clump c = fill_clump(kCube, v, {n});
    EXPECT_EQ(c.size(), static_cast<std::size_t>(n));
    expect_inscribed(kCube, c);
  }
  // The first sphere is the largest inscribed one, at the centre.
  const Clump one = fill_clump(kCube, v, {1});
  EXPECT_LT(one.centers[0].norm(), 1e-12);
  EXPECT_NEAR(one.radii[0], 0.5, 1e-12);
}

TEST(FillClump, ShapeErrorDecreasesWithMoreSpheres) {
  const Voxels v = voxelize(kCube, 1.0 / 41);
  double prev = 1e9, prev_dev = 1e9;
  for (int n : {1, 10, 30, 100, 300}) {
    const ClumpQuality q = clump_quality(fill_clump(kCube, v, {n}), v);
    std::printf("cube fill %3d spheres: volume error %.4f, max deviation %.4f\n", n, q.volume_error,
                q.max_deviation);
    EXPECT_LT(q.volume_error, prev);
    EXPECT_LE(q.max_deviation, prev_dev);  // coverage only grows
    prev = q.volume_error;
    prev_dev = q.max_deviation;
  }
  // One inscribed sphere misses 1 - pi/6 of the cube.
  EXPECT_NEAR(clump_quality(fill_clump(kCube, v, {1}), v).volume_error, 1 - M_PI / 6, 0.02);
}

TEST(FillClump, WorksOnMeshesAndStopsWhenEverythingIsCovered) {
  const TriangleMesh ico = icosphere_mesh(0.5, 1);
  check_closed_oriented(ico, "icosphere");
  const SolidGeometry s = SolidGeometry::mesh(ico);
  const Voxels v = voxelize(s, 1.0 / 24);
  const Clump c = fill_clump(s, v, {20});
  expect_inscribed(s, c);
  EXPECT_EQ(c.size(), 20u);
  const ClumpQuality q = clump_quality(c, v);
  EXPECT_LT(q.volume_error, 0.1);
  // A sphere: one sphere covers every voxel except those within round-off of the surface.
  const SolidGeometry ball = SolidGeometry::sphere(0.5);
  const Voxels vb = voxelize(ball, 1.0 / 30);
  const Clump cb = fill_clump(ball, vb, {13});
  EXPECT_EQ(cb.size(), 1u);
  EXPECT_LT(clump_quality(cb, vb).volume_error, 1e-3);
}

TEST(ClumpQuality, IdenticalUnionHasNoError) {
  const SolidGeometry ball = SolidGeometry::sphere(0.4);
  const Voxels v = voxelize(ball, 0.02);
  Clump c;
  c.centers.push_back(Eigen::Vector3d::Zero());
  c.radii.push_back(0.4);
  const ClumpQuality q = clump_quality(c, v);
  EXPECT_EQ(q.volume_error, 0.0);
  EXPECT_EQ(q.max_deviation, 0.0);
  // A sphere 10 % too big deviates by about 0.04 (to within the lattice resolution).
  c.radii[0] = 0.44;
  const ClumpQuality big = clump_quality(c, v);
  EXPECT_NEAR(big.max_deviation, 0.04, 0.02);
  EXPECT_NEAR(big.volume_error, 1.1 * 1.1 * 1.1 - 1, 0.05);
}

TEST(ClumpIo, RoundTrip) {
  test::TempFile f("rt.clump");
  const Voxels v = voxelize(kCube, 1.0 / 21);
  const Clump c = surface_clump(kCube, v, {5, 1.0, true});
  write_clump(f.str(), c, {"test clump", "method: surface grid=5"});
  const Clump back = read_clump(f.str());
  ASSERT_EQ(back.size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_NEAR((back.centers[i] - c.centers[i]).norm(), 0.0, 1e-9);
    EXPECT_NEAR(back.radii[i], c.radii[i], 1e-9);
  }
  const Clump scaled = read_clump(f.str(), 2e-3);
  EXPECT_NEAR(scaled.radii[0], 2e-3 * c.radii[0], 1e-12);
}

TEST(ClumpIo, BadLinesNameFileAndLine) {
  test::TempFile f("bad.clump");
  {
    std::ofstream o(f.str());
    o << "# header\n0 0 0 0.5\n0 0 1\n";
  }
  try {
    read_clump(f.str());
    FAIL() << "expected a ShapeError";
  } catch (const ShapeError& e) {
    EXPECT_NE(std::string(e.what()).find(f.str() + ":3: expected 'x y z r'"), std::string::npos)
        << e.what();
  }
  {
    std::ofstream o(f.str());
    o << "0 0 0 -0.5\n";
  }
  EXPECT_THROW(read_clump(f.str()), ShapeError);
  {
    std::ofstream o(f.str());
    o << "# only comments\n";
  }
  EXPECT_THROW(read_clump(f.str()), ShapeError);
}

}  // namespace
}  // namespace lbdem
