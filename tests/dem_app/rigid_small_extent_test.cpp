// The extent rigid/small checks against the ghost cutoff (dem_app/engine/lammps_input.hpp):
// measured from the owning sphere, not from the centroid.
#include <gtest/gtest.h>

#include <cmath>

#include "dem_app/engine/lammps_input.hpp"

namespace lbdem {
namespace {

DemSetup one_body(const Clump& clump, const std::array<double, 4>& orientation) {
  DemSetup s;
  Shape shape;
  shape.clump = clump;
  s.shapes = {shape};
  BodyParams b;
  b.position = {0.3, 0.2, 0.1};
  b.orientation = orientation;
  b.density = 1000;
  s.bodies = {b};
  return s;
}

// Eight spheres on a ring of radius R: the centroid is empty, every sphere is equally near the
// centre of the bounding box, the first owns the body and the opposite one is 2 R away, more
// than the clump's reach R + r from the centroid.
TEST(RigidSmallExtent, RingIsMeasuredAcrossTheHole) {
  const double ring = 0.5, r = 0.1, pi = std::acos(-1.0);
  Clump c;
  for (int k = 0; k < 8; ++k) {
    c.centers.emplace_back(ring * std::cos(k * pi / 4), ring * std::sin(k * pi / 4), 0);
    c.radii.push_back(r);
  }
  for (const auto& q : {std::array<double, 4>{1, 0, 0, 0}, std::array<double, 4>{0.8, 0.6, 0, 0}}) {
    const DemSetup s = one_body(c, q);
    EXPECT_NEAR(rigid_small_extent(s), 2 * ring, 1e-12);
    EXPECT_GT(rigid_small_extent(s), clump_extent(s.shapes[0]));
  }
}

// A sphere centred on its centroid: LAMMPS gets three helper spheres 1e-3 r from it, and the
// centre sphere (first of four equally near ones) owns the body.
TEST(RigidSmallExtent, OneSphereReachesItsHelpers) {
  Clump c;
  c.centers = {Eigen::Vector3d::Zero()};
  c.radii = {0.2};
  EXPECT_NEAR(rigid_small_extent(one_body(clump_for_lammps(c), {1, 0, 0, 0})), 2e-4, 1e-15);
}

}  // namespace
}  // namespace lbdem
