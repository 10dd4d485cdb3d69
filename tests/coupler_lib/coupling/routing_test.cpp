#include <gtest/gtest.h>

#include "coupler_lib/coupling/routing.hpp"

namespace lbdem {
namespace {

// A 1 x 1 x 1 box split into four slabs along x, periodic along x and z.
FluidLayout slabs() {
  FluidLayout l;
  l.domain.hi = {1, 1, 1};
  l.periodic = {true, false, true};
  for (int r = 0; r < 4; ++r) {
    Box b = l.domain;
    b.lo[0] = 0.25 * r;
    b.hi[0] = 0.25 * (r + 1);
    l.boxes.push_back(b);
  }
  l.shape_radius = {0.05};
  l.margin = 0.02;
  return l;
}

TEST(Routing, InteriorBodyTouchesOnlyItsSlab) {
  const double x[3] = {0.4, 0.5, 0.5};
  EXPECT_EQ(touched_ranks(slabs(), x, 0.07), (std::vector<int>{1}));
}

TEST(Routing, BodyNearInternalFaceTouchesBothSides) {
  const double x[3] = {0.49, 0.5, 0.5};
  EXPECT_EQ(touched_ranks(slabs(), x, 0.07), (std::vector<int>{1, 2}));
}

TEST(Routing, ReachIsInclusiveAndExact) {
  const double x[3] = {0.45, 0.5, 0.5};
  EXPECT_EQ(touched_ranks(slabs(), x, 0.05), (std::vector<int>{1, 2}));
  EXPECT_EQ(touched_ranks(slabs(), x, 0.0499), (std::vector<int>{1}));
}

TEST(Routing, PeriodicImageAcrossTheDomainEnd) {
  const double x[3] = {0.98, 0.5, 0.5};
  EXPECT_EQ(touched_ranks(slabs(), x, 0.07), (std::vector<int>{0, 3}));
}

TEST(Routing, UnwrappedPositionsUseTheirImages) {
  const double ahead[3] = {1.98, 0.5, 0.5}, behind[3] = {-0.02, 0.5, 0.5};
  EXPECT_EQ(touched_ranks(slabs(), ahead, 0.07), (std::vector<int>{0, 3}));
  EXPECT_EQ(touched_ranks(slabs(), behind, 0.07), (std::vector<int>{0, 3}));
}

TEST(Routing, WallAxisHasNoImages) {
  FluidLayout l = slabs();
  // Split along y (a wall axis) instead: a body at the top must not reach the bottom slab.
  for (int r = 0; r < 4; ++r) {
    l.boxes[r] = l.domain;
    l.boxes[r].lo[1] = 0.25 * r;
    l.boxes[r].hi[1] = 0.25 * (r + 1);
  }
  const double x[3] = {0.5, 0.99, 0.5};
  EXPECT_EQ(touched_ranks(l, x, 0.07), (std::vector<int>{3}));
}

TEST(Routing, CornerUsesSphereDistanceNotBoxOverlap) {
  FluidLayout l;
  l.domain.hi = {2, 2, 1};
  l.periodic = {false, false, false};
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      Box b = l.domain;
      b.lo = {1.0 * i, 1.0 * j, 0};
      b.hi = {1.0 * (i + 1), 1.0 * (j + 1), 1};
      l.boxes.push_back(b);
    }
  // 0.09 from both faces near the corner (1, 1): the diagonal box is 0.127 away.
  const double x[3] = {0.91, 0.91, 0.5};
  EXPECT_EQ(touched_ranks(l, x, 0.1), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(touched_ranks(l, x, 0.13), (std::vector<int>{0, 1, 2, 3}));
}

TEST(Routing, PeriodicCornerImageInTwoAxes) {
  FluidLayout l;
  l.domain.hi = {1, 1, 1};
  l.periodic = {true, true, true};
  Box b;
  b.lo = {0, 0, 0};
  b.hi = {0.5, 0.5, 0.5};
  l.boxes = {b};
  const double x[3] = {0.97, 0.97, 0.75};  // 0.03 from the box's image in x and y
  EXPECT_NEAR(periodic_distance2(l, b, x), 0.03 * 0.03 * 2 + 0.25 * 0.25, 1e-12);
}

TEST(Routing, ReachAddsMarginAndRejectsUnknownShape) {
  const FluidLayout l = slabs();
  EXPECT_DOUBLE_EQ(l.reach(0), 0.07);
  EXPECT_THROW(l.reach(1), std::out_of_range);
}

TEST(Routing, LayoutRoundTripAndValidation) {
  const FluidLayout l = slabs();
  const FluidLayout back = unpack_layout(pack_layout(l));
  EXPECT_EQ(pack_layout(back), pack_layout(l));
  EXPECT_EQ(back.periodic, l.periodic);
  EXPECT_NO_THROW(validate_layout(l));
  FluidLayout bad = l;
  bad.boxes[2].hi[0] = 1.5;
  EXPECT_THROW(validate_layout(bad), std::invalid_argument);
  std::vector<double> flat = pack_layout(l);
  flat.pop_back();
  EXPECT_THROW(unpack_layout(flat), std::invalid_argument);
}

}  // namespace
}  // namespace lbdem
