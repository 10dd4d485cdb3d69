// Exact inside tests and distances to the surface of the solids (used by the clump
// generators for sphere radii and by the surface method's fit test).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/solid_geometry.hpp"

namespace lbdem {
namespace {

// Dense sample of the ellipsoid surface, for reference distances.
std::vector<Eigen::Vector3d> ellipsoid_samples(const Eigen::Vector3d& e, int n) {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i <= n; ++i) {
    const double th = std::numbers::pi * i / n;
    for (int j = 0; j < 2 * n; ++j) {
      const double ph = std::numbers::pi * j / n;
      out.emplace_back(e.x() * std::sin(th) * std::cos(ph), e.y() * std::sin(th) * std::sin(ph),
                       e.z() * std::cos(th));
    }
  }
  return out;
}

double sampled_distance(const std::vector<Eigen::Vector3d>& samples, const Eigen::Vector3d& p) {
  double best = 1e300;
  for (const auto& x : samples) best = std::min(best, (x - p).squaredNorm());
  return std::sqrt(best);
}

TEST(SolidGeometry, EllipsoidDistanceMatchesSampling) {
  const Eigen::Vector3d e(1.0, 0.6, 0.3);
  const SolidGeometry g = SolidGeometry::ellipsoid(e);
  const auto samples = ellipsoid_samples(e, 500);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  for (int t = 0; t < 15; ++t) {
    const Eigen::Vector3d p(u(rng), 0.7 * u(rng), 0.5 * u(rng));
    const double exact = g.distance_to_surface(p);
    const double sampled = sampled_distance(samples, p);
    // Sampling can only overestimate, by at most about the sample spacing squared / (2 d).
    EXPECT_LE(exact, sampled + 1e-12) << p.transpose();
    EXPECT_NEAR(exact, sampled, 2e-4) << p.transpose();
  }
  // Inside, on the plane of the smallest axis: the nearest point leaves that plane.
  EXPECT_NEAR(g.distance_to_surface({0, 0, 0}), 0.3, 1e-12);
  // Round-off away from the centre (a voxel centroid) must not divide by zero.
  EXPECT_NEAR(g.distance_to_surface({1e-17, -2e-17, 3e-17}), 0.3, 1e-12);
  EXPECT_NEAR(g.distance_to_surface({0.2, 1e-16, 1e-16}), 0.3 * std::sqrt(1 - 0.04 / 0.91), 1e-9);
  EXPECT_NEAR(g.distance_to_surface({0.1, 0.05, 0}), sampled_distance(samples, {0.1, 0.05, 0}),
              2e-4);
  EXPECT_NEAR(g.distance_to_surface({1.5, 0, 0}), 0.5, 1e-12);
}

TEST(SolidGeometry, MeshBoxAgreesWithAnalyticBox) {
  const Eigen::Vector3d edges(1.0, 0.5, 0.8);
  const SolidGeometry box = SolidGeometry::cuboid(edges);
  const SolidGeometry mesh = SolidGeometry::mesh(box_mesh(edges));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  for (int t = 0; t < 500; ++t) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    EXPECT_EQ(box.inside(p), mesh.inside(p)) << p.transpose();
    EXPECT_NEAR(box.distance_to_surface(p), mesh.distance_to_surface(p), 1e-12) << p.transpose();
  }
  EXPECT_NEAR(mesh.exact_volume(), edges.prod(), 1e-14);
}

TEST(SolidGeometry, SphereAndIcosphere) {
  const SolidGeometry s = SolidGeometry::sphere(0.5);
  EXPECT_TRUE(s.inside({0.49, 0, 0}));
  EXPECT_FALSE(s.inside({0.5, 0, 0}));
  EXPECT_NEAR(s.distance_to_surface({0.1, 0.2, 0.2}), 0.2, 1e-15);
  const SolidGeometry ico = SolidGeometry::mesh(icosphere_mesh(0.5, 3));
  // Inscribed polyhedron: the centre is a little less deep than in the sphere.
  const double d = ico.distance_to_surface(Eigen::Vector3d::Zero());
  EXPECT_LT(d, 0.5);
  EXPECT_GT(d, 0.49);
}

}  // namespace
}  // namespace lbdem
