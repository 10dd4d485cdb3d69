// Voxelization and mass properties against analytic volumes and inertias: the exact mass
// properties of the solids (closed forms, polyhedral integrals) and the volume fractions of
// the reference lattice; STL round trips against analytic shapes.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "coupler_lib/geometry/mass_properties.hpp"
#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/stl_io.hpp"
#include "coupler_lib/geometry/voxelize.hpp"
#include "temp_file.hpp"

namespace lbdem {
namespace {

constexpr double kPi = std::numbers::pi;

struct Errors {
  double volume = 0;    // relative
  double inertia = 0;   // max relative error of the diagonal
  double centroid = 0;  // |c| / size
};

Errors errors(const MassProperties& m, double volume, const Eigen::Vector3d& inertia_diag,
              double size) {
  Errors e;
  e.volume = std::abs(m.volume - volume) / volume;
  for (int d = 0; d < 3; ++d)
    e.inertia = std::max(e.inertia, std::abs(m.inertia(d, d) - inertia_diag[d]) / inertia_diag[d]);
  e.centroid = m.centroid.norm() / size;
  return e;
}

// The fluid's view of a body: the volume fractions of its reference lattice hold the
// body's volume to a small fraction of a voxel layer, at spacings that are not simple
// fractions of the size (0/1 voxels are off by up to a few percent here, printed). The
// lattice's inertia (a diagnostic only: the DEM takes the exact one) places each partial
// voxel's solid at the voxel centre, a first-order error bounded by h / (2 size).
TEST(Voxelize, SphereFillHoldsVolumeAndInertia) {
  const double R = 0.5;
  const double V = 4.0 / 3.0 * kPi * R * R * R;
  const Eigen::Vector3d I = Eigen::Vector3d::Constant(0.4 * V * R * R);
  const auto geom = SolidGeometry::sphere(R);
  const auto t0 = std::chrono::steady_clock::now();
  for (double cells : {9.3, 18.6, 37.2}) {
    const Voxels v = voxelize(geom, 2 * R / cells);
    const Errors e = errors(mass_properties(v), V, I, 2 * R);
    const double binary = std::abs(static_cast<double>(v.count()) * std::pow(v.h, 3) / V - 1);
    std::printf(
        "sphere D/h=%5.1f  fill: volume err %.3e  inertia err %.3e  centroid %.1e; "
        "0/1 voxels: volume err %.3e\n",
        cells, e.volume, e.inertia, e.centroid, binary);
    EXPECT_LT(e.volume, 2e-3);
    EXPECT_LT(e.inertia, 0.5 / cells);
    EXPECT_LT(e.centroid, 1e-12);  // the lattice is centred on the body
  }
  std::printf("  (%.2f s)\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

TEST(Voxelize, EllipsoidFillHoldsVolumeAndInertia) {
  const Eigen::Vector3d a(0.6, 0.35, 0.2);
  const double V = 4.0 / 3.0 * kPi * a.prod();
  const Eigen::Vector3d I(V * (a.y() * a.y() + a.z() * a.z()) / 5,
                          V * (a.x() * a.x() + a.z() * a.z()) / 5,
                          V * (a.x() * a.x() + a.y() * a.y()) / 5);
  const auto geom = SolidGeometry::ellipsoid(a);
  for (double cells : {10.3, 20.6, 41.2}) {
    const Errors e = errors(mass_properties(voxelize(geom, 2 * a.z() / cells)), V, I, 2 * a.x());
    std::printf("ellipsoid 2c/h=%5.1f  volume err %.3e  inertia err %.3e\n", cells, e.volume,
                e.inertia);
    EXPECT_LT(e.volume, 2e-3);
    EXPECT_LT(e.inertia, 0.5 / cells);
  }
}

// A cube of 19.4 reference cells (the study's cube at 12 cells per sphere diameter): its 0/1
// voxels hold 20^3 cells, 9.6 % too many; the fractions hold its volume exactly.
TEST(Voxelize, MisalignedCuboidFillIsExact) {
  const double h = 1.0 / 19.4;
  const Voxels v = voxelize(SolidGeometry::cuboid({1, 1, 1}), h);
  const MassProperties m = mass_properties(v);
  const double binary = static_cast<double>(v.count()) * h * h * h;
  std::printf("cube a/h = 19.4: fill volume %.12f, 0/1 voxels %.4f\n", m.volume, binary);
  EXPECT_NEAR(m.volume, 1.0, 1e-6);  // float fractions
  EXPECT_GT(std::abs(binary - 1.0), 0.05);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(m.inertia(d, d), 1.0 / 6.0, 0.5 * h / 6.0);
}

TEST(Voxelize, LatticeAlignedCuboidIsExact) {
  const Eigen::Vector3d edges(1.0, 0.5, 0.25);
  const double V = edges.prod();
  const Eigen::Vector3d I(V * (0.25 + 0.0625) / 12, V * (1.0 + 0.0625) / 12, V * (1.0 + 0.25) / 12);
  const MassProperties m = mass_properties(voxelize(SolidGeometry::cuboid(edges), 0.0625));
  EXPECT_NEAR(m.volume, V, 1e-12);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(m.inertia(d, d), I[d], 1e-12 * I[d]);
  EXPECT_NEAR(m.inertia(0, 1), 0.0, 1e-15);
  EXPECT_LT(m.centroid.norm(), 1e-14);
}

// The fluid's reference lattice (box_averaged): each voxel holds the solid fraction of the cube
// of side 2 h about its centre, taking each voxel's fill as spread evenly over it. For a box
// whose faces lie on voxel faces (fills 0 or 1) that is exact: a product of per-axis overlaps.
// Any solid keeps its total volume.
TEST(Voxelize, BoxAveragedFillIsTheFractionOfABoxTwiceTheSpacing) {
  const double h = 1.0 / 20;
  const Voxels v = box_averaged(voxelize(SolidGeometry::cuboid({1, 1, 1}), h));
  auto overlap = [&](double c) {  // of [c - h, c + h] with [-1/2, 1/2], over 2 h
    return std::max(0.0, std::min(c + h, 0.5) - std::max(c - h, -0.5)) / (2 * h);
  };
  double worst = 0;
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const Eigen::Vector3d c = v.center(i, j, k);
        const double exact = overlap(c.x()) * overlap(c.y()) * overlap(c.z());
        worst = std::max(worst, std::abs(v.fill[v.index(i, j, k)] - exact));
      }
  EXPECT_LT(worst, 1e-7);
  const Voxels s = box_averaged(voxelize(SolidGeometry::sphere(0.5), 1.0 / 19.4));
  EXPECT_NEAR(mass_properties(s).volume,
              mass_properties(voxelize(SolidGeometry::sphere(0.5), 1.0 / 19.4)).volume, 1e-6);
}

TEST(Voxelize, KeepsEmptyLayersAroundTheSolid) {
  const Voxels v = voxelize(SolidGeometry::sphere(0.5), 0.05, 2);
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const bool rim =
            i < 2 || j < 2 || k < 2 || i >= v.n[0] - 2 || j >= v.n[1] - 2 || k >= v.n[2] - 2;
        if (rim) {
          ASSERT_EQ(v.solid[v.index(i, j, k)], 0) << i << " " << j << " " << k;
        }
      }
}

// A cube mesh, read back from STL in both formats, gives exactly the analytic cube's voxels.
// The columns x = y pass exactly through the diagonal edges of the top and bottom faces.
TEST(Voxelize, StlCubeRoundTripEqualsAnalyticCube) {
  const double a = 1.0, h = 1.0 / 16;
  const Voxels ref = voxelize(SolidGeometry::cuboid({a, a, a}), h);
  for (bool binary : {false, true}) {
    test::TempFile f(binary ? "rt_cube.stlb" : "rt_cube.stl");
    binary ? write_stl_binary(f.str(), box_mesh({a, a, a}))
           : write_stl_ascii(f.str(), box_mesh({a, a, a}));
    const Voxels v = voxelize_mesh(read_stl(f.str()), h);
    ASSERT_EQ(v.n, ref.n);
    EXPECT_EQ(v.solid, ref.solid);
    const MassProperties m = mass_properties(v), r = mass_properties(ref);
    EXPECT_EQ(m.volume, r.volume);
    EXPECT_NEAR((m.inertia - r.inertia).norm(), 0.0, 1e-15);
    EXPECT_NEAR(m.volume, 1.0, 1e-6);
    EXPECT_EQ(v.fill, ref.fill);
  }
}

// Columns through mesh vertices and edges: the octahedron's apexes lie exactly on the
// central column and its edges in the planes x = 0 and y = 0 that hold lattice columns.
TEST(Voxelize, RayParityIsExactThroughVerticesAndEdges) {
  const double a = 1.0, h = 2.0 / 21;  // 21 voxels across: a column at x = y = 0
  const Voxels v = voxelize_mesh(octahedron_mesh(a), h);
  std::size_t mismatch = 0;
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const Eigen::Vector3d p = v.center(i, j, k);
        const bool in = p.cwiseAbs().sum() < a;
        mismatch += v.solid[v.index(i, j, k)] != in;
      }
  EXPECT_EQ(mismatch, 0u);
  EXPECT_TRUE(v.solid[v.index(v.n[0] / 2, v.n[1] / 2, v.n[2] / 2)]);
}

// The icosphere STL against the analytic sphere: the voxels may differ only in the thin
// shell between the inscribed polyhedron and the sphere.
TEST(Voxelize, StlIcosphereMatchesAnalyticSphereUpToFacetting) {
  const double R = 0.5, h = 1.0 / 40;
  const TriangleMesh ico = icosphere_mesh(R, 3);
  test::TempFile f("rt_ico.stl");
  write_stl_binary(f.str(), ico);
  const Voxels v = voxelize_mesh(read_stl(f.str()), h);
  const Voxels ref = voxelize(SolidGeometry::sphere(R), h);
  ASSERT_EQ(v.n, ref.n);
  // Largest gap between a level-3 icosphere and its sphere (at face centres), bounded by
  // R (1 - cos(theta)) with theta the largest vertex-to-face-centre angle, < 0.02 R.
  const double gap = 0.02 * R;
  std::size_t extra = 0, missing_far = 0;
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const auto id = v.index(i, j, k);
        const double r = v.center(i, j, k).norm();
        if (v.solid[id] && !ref.solid[id]) ++extra;  // mesh is inside the sphere
        if (!v.solid[id] && ref.solid[id] && r < R - gap) ++missing_far;
      }
  EXPECT_EQ(extra, 0u);
  EXPECT_EQ(missing_far, 0u);
  const MassProperties m = mass_properties(v), r = mass_properties(ref);
  const double rel = std::abs(m.volume - signed_volume(ico)) / signed_volume(ico);
  std::printf("icosphere fill volume vs mesh volume: %.3e; vs sphere fill: %.3e\n", rel,
              std::abs(m.volume - r.volume) / r.volume);
  EXPECT_LT(rel, 1e-3);
}

// The exact mass properties of a mesh (polyhedral integrals) against the closed forms.
TEST(MassProperties, MeshIntegralsAreExact) {
  const Eigen::Vector3d edges(1.0, 0.6, 0.3);
  const MassProperties box = mass_properties(SolidGeometry::cuboid(edges));
  TriangleMesh mesh = box_mesh(edges);
  const Eigen::Vector3d shift(10.1, -20.2, 30.3);  // far from the origin: no cancellation
  transform_mesh(mesh, Eigen::Matrix3d::Identity(), shift);
  const MassProperties m = mass_properties(SolidGeometry::mesh(mesh));
  EXPECT_NEAR(m.volume, edges.prod(), 1e-13);
  EXPECT_NEAR((m.centroid - shift).norm(), 0.0, 1e-12);
  EXPECT_NEAR((m.inertia - box.inertia).norm(), 0.0, 1e-13);
  EXPECT_NEAR(box.inertia(0, 0), edges.prod() * (0.36 + 0.09) / 12, 1e-15);
  const MassProperties ball = mass_properties(SolidGeometry::sphere(0.5));
  EXPECT_NEAR(ball.inertia(1, 1), 0.4 * ball.volume * 0.25, 1e-15);
}

TEST(MassProperties, PrincipalAxesOfARotatedCuboid) {
  const Eigen::Vector3d edges(1.0, 0.6, 0.3);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
                             Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  TriangleMesh mesh = box_mesh(edges);
  transform_mesh(mesh, R, Eigen::Vector3d(0.1, -0.2, 0.3));
  const MassProperties m = mass_properties(voxelize_mesh(mesh, 1.0 / 60));
  const MassProperties exact = mass_properties(SolidGeometry::mesh(mesh));
  const double V = edges.prod();
  // Body-frame moments: I_x = V (b^2 + c^2)/12 etc.; ascending order is x, y, z reversed.
  const Eigen::Vector3d I(V * (0.36 + 0.09) / 12, V * (1.0 + 0.09) / 12, V * (1.0 + 0.36) / 12);
  // Ascending: largest edge has the smallest moment -> x, then y, then z.
  const Eigen::Vector3d expect(I[0], I[1], I[2]);
  std::printf("rotated cuboid moments %.5f %.5f %.5f, expected %.5f %.5f %.5f\n",
              m.principal_moments[0], m.principal_moments[1], m.principal_moments[2], expect[0],
              expect[1], expect[2]);
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(m.principal_moments[d], expect[d], 3e-3 * expect[d]);
    EXPECT_NEAR(exact.principal_moments[d], expect[d], 1e-12 * expect[d]);
    EXPECT_GT(std::abs(exact.principal_axes.col(d).dot(R.col(d))), 1 - 1e-12);
    const double c = std::abs(m.principal_axes.col(d).dot(R.col(d)));
    std::printf("  axis %d: 1 - |cos| to the true axis = %.1e\n", d, 1 - c);
    EXPECT_GT(c, 0.999);
  }
  EXPECT_NEAR(m.principal_axes.determinant(), 1.0, 1e-12);
  EXPECT_NEAR((m.centroid - Eigen::Vector3d(0.1, -0.2, 0.3)).norm(), 0.0, 2e-3);
  // The tensor reconstructed from the eigen-decomposition is the tensor.
  const Eigen::Matrix3d back =
      m.principal_axes * m.principal_moments.asDiagonal() * m.principal_axes.transpose();
  EXPECT_NEAR((back - m.inertia).norm(), 0.0, 1e-12 * m.inertia.norm());
}

TEST(MassProperties, BoundingRadiusIsTheFarthestVoxelCorner) {
  const Voxels v = voxelize(SolidGeometry::cuboid({1, 1, 1}), 0.125);
  EXPECT_NEAR(bounding_radius(v, Eigen::Vector3d::Zero()), std::sqrt(3.0) / 2, 1e-12);
  const Voxels s = voxelize(SolidGeometry::sphere(0.5), 0.05);
  const double r = bounding_radius(s, Eigen::Vector3d::Zero());
  EXPECT_GE(r, 0.5 - 1e-12);
  EXPECT_LE(r, 0.5 + std::sqrt(3.0) * 0.05);
}

TEST(Voxels, SolidAtLooksUpTheCellContainingThePoint) {
  const Voxels v = voxelize(SolidGeometry::cuboid({1, 1, 1}), 0.25);
  EXPECT_EQ(v.solid_at({0.1, 0.1, 0.1}), 1);
  EXPECT_EQ(v.solid_at({0.49, -0.49, 0.2}), 1);
  EXPECT_EQ(v.solid_at({0.51, 0.0, 0.0}), 0);
  EXPECT_EQ(v.solid_at({100, 0, 0}), 0);  // off the lattice
}

}  // namespace
}  // namespace lbdem
