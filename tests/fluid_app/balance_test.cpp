// The balanced decomposition: cuts that split each axis's work into equal shares
// (fluid_app/parallel/decomposition.hpp) and the work of the initial bodies per slice
// (fluid_app/parallel/balance.hpp).
#include <gtest/gtest.h>

#include <numeric>

#include "fluid_app/parallel/balance.hpp"
#include "fluid_app/parallel/decomposition.hpp"

namespace lbdem {
namespace {

std::vector<Extent> blocks(const std::vector<double>& w, int p) {
  std::vector<Extent> out;
  for (int r = 0; r < p; ++r) out.push_back(weighted_extent(w, p, r));
  return out;
}

void expect_tiling(const std::vector<Extent>& b, int n) {
  int next = 0;
  for (const Extent& e : b) {
    EXPECT_EQ(e.offset, next);
    EXPECT_GE(e.count, 1);
    next = e.offset + e.count;
  }
  EXPECT_EQ(next, n);
}

double weight_of(const std::vector<double>& w, const Extent& e) {
  return std::accumulate(w.begin() + e.offset, w.begin() + e.offset + e.count, 0.0);
}

TEST(WeightedExtent, UniformWeightsGiveEqualBlocks) {
  const std::vector<double> w(12, 1.0);
  const auto b = blocks(w, 4);
  expect_tiling(b, 12);
  for (const Extent& e : b) EXPECT_EQ(e.count, 3);
}

TEST(WeightedExtent, HeavySlicesGetNarrowBlocks) {
  // A bed: the lowest 10 of 40 slices weigh 10 times the rest.
  std::vector<double> w(40, 1.0);
  for (int i = 0; i < 10; ++i) w[std::size_t(i)] = 10.0;
  const int p = 4;
  const auto b = blocks(w, p);
  expect_tiling(b, 40);
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  for (const Extent& e : b) EXPECT_LE(weight_of(w, e), total / p + 10.0) << e.offset;
  EXPECT_LT(b[0].count, b[3].count);
}

TEST(WeightedExtent, EveryBlockKeepsACellWhenTheWorkIsInOneSlice) {
  std::vector<double> w(6, 0.0);
  w[0] = 100.0;
  expect_tiling(blocks(w, 6), 6);
  expect_tiling(blocks(w, 3), 6);
}

TEST(BodyWorkWeights, EveryAxisCountsTheSameWorkAndWrapsPeriodicFaces) {
  FluidParams f;
  f.cells = {20, 16, 12};
  f.dx = 1.0;
  f.covered_cell_weight = 5;
  Shape sphere;
  sphere.mass.volume = 4.0 / 3.0 * 3.14159265358979 * 27.0;  // radius 3 cells
  BodyParams b;
  b.position = {0.5, 8.0, 6.0};  // on the x_min face: wraps to the x_max slices
  const auto w = body_work_weights(f, {b}, {sphere});
  const double cells = 20.0 * 16 * 12;
  std::array<double, 3> total{};
  for (int a = 0; a < 3; ++a) total[a] = std::accumulate(w[a].begin(), w[a].end(), 0.0);
  // Cells plus 4 x the covered volume of a sphere of radius 4.5 (3 + the band's 1.5 cells),
  // summed over slices: the same on every axis, within the slice quadrature.
  const double covered = 4.0 / 3.0 * 3.14159265358979 * 4.5 * 4.5 * 4.5;
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(total[a], cells + 4 * covered, 0.03 * 4 * covered) << a;
  EXPECT_GT(w[0][19], w[0][10]);  // the image across the periodic x faces
  EXPECT_GT(w[0][0], w[0][10]);
  EXPECT_DOUBLE_EQ(w[0][10], 16.0 * 12);  // far from the body: plain cells only
}

}  // namespace
}  // namespace lbdem
