// The surface-only porosity update (paper: "only the nodes currently covered by a body and a
// surrounding growth layer have to be revisited") against a full recomputation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <vector>

#include "tests/fluid_app/hlbm/hlbm_fixtures.hpp"

namespace lbdem::hlbm {
namespace {

using test::state;

struct Motion {
  Eigen::Vector3d x, v, w;  // centre (cells), velocity (cells/step), angular velocity (rad/step)
  Eigen::Quaterniond q{1, 0, 0, 0};
  int shape = 0;
  std::int64_t id = 0;
  void advance() {
    x += v;
    const double angle = w.norm();
    if (angle > 0) q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle)) * q;
    q.normalize();
  }
  BodyState packet() const { return state(id, x, q, v, w, shape); }
};

void expect_same_field(const PorousField<double>& a, const PorousField<double>& b, int step) {
  ASSERT_EQ(a.d.size(), b.d.size());
  for (std::size_t c = 0; c < a.d.size(); ++c) {
    ASSERT_EQ(a.d[c], b.d[c]) << "step " << step << " cell " << c;
    ASSERT_EQ(a.body[c], b.body[c]) << "step " << step << " cell " << c;
  }
}

// One step of both fields: the incremental update and a full recomputation from the same states
// must give the same field, with no cell inside two bodies. Adds the update's counts.
void update_both(BodyField<double>& inc, BodyField<double>& full, const PorousField<double>& fi,
                 const PorousField<double>& ff, const std::vector<BodyState>& states, int step,
                 std::size_t& evaluations, std::size_t& scans) {
  const UpdateStats s = inc.update(states);
  full.update(states, UpdateMode::full);
  evaluations += s.evaluated;
  scans += s.full_scans;
  EXPECT_EQ(s.interior_conflicts, 0u) << "step " << step;
  expect_same_field(fi, ff, step);
}

void incremental_equals_full(PorosityLookup lookup) {
  // A rotating cube and a sphere cross the periodic boundary in x, the block boundaries of a
  // rank holding x in [5, 22) of 40 cells, pass close to each other, one leaves and comes
  // back, and one jumps.
  const Shape shapes[2] = {test::cube(7, 0.5), test::sphere(4.5, 0.5)};
  const Subdomain sub = test::subdomain({40, 40, 40}, {5, 0, 0}, {17, 40, 40});
  PorousField<double> fi, ff;
  BodyField<double> inc(shapes, sub, test::unit_frame(), fi, lookup);
  BodyField<double> full(shapes, sub, test::unit_frame(), ff, lookup);
  std::vector<Motion> m(2);
  m[0] = {Eigen::Vector3d(30, 20.3, 19.7), Eigen::Vector3d(0.25, 0.05, -0.02),
          Eigen::Vector3d(0.01, 0.02, 0.015)};
  m[0].id = 11;
  m[1] = {Eigen::Vector3d(8.2, 10.1, 8.0), Eigen::Vector3d(0.1, 0.3, 0.0),
          Eigen::Vector3d(0.0, 0.0, 0.02)};
  m[1].shape = 1;
  m[1].id = 5;
  std::size_t evaluations = 0, full_scans = 0;
  for (int step = 0; step < 70; ++step) {
    std::vector<BodyState> states;
    for (const Motion& b : m)
      if (!(b.id == 5 && step >= 30 && step < 34)) states.push_back(b.packet());  // 5 away
    if (step == 50) m[1].x += Eigen::Vector3d(3, 0, 0);  // a jump of 3 cells
    update_both(inc, full, fi, ff, states, step, evaluations, full_scans);
    if (::testing::Test::HasFatalFailure()) return;
    for (Motion& b : m) b.advance();
  }
  std::printf("70 steps: %zu evaluations, %zu support scans\n", evaluations, full_scans);
  // 2 first appearances, 1 removal, 1 re-appearance, 1 jump (removal + embedding).
  EXPECT_EQ(full_scans, 6u);
}

TEST(BandUpdate, IncrementalEqualsFullAcrossRankAndPeriodicBoundaries) {
  incremental_equals_full(PorosityLookup::trilinear);
}

// The nearest-voxel lookup (the paper's) has a narrower band and d in steps of 1/19; the
// surface-only update must still find every changed cell.
TEST(BandUpdate, IncrementalEqualsFullWithNearestLookup) {
  incremental_equals_full(PorosityLookup::nearest);
}

// The motion of a settling suspension: many updates of small random moves and turns (0 to 0.08
// cells, 0 to 0.01 rad), each body its own, so the batched band search (the old band dilated,
// then grown from the new band cells) runs almost every update on a band that moved by a
// fraction of a cell; a cube and a sphere, both lookups, against a full recomputation.
void small_random_moves_equal_full(PorosityLookup lookup) {
  const Shape shapes[2] = {test::cube(6.5, 0.5), test::sphere(3.7, 0.5)};
  const Subdomain sub = test::subdomain({36, 36, 36}, {0, 0, 0}, {36, 36, 36});
  PorousField<double> fi, ff;
  BodyField<double> inc(shapes, sub, test::unit_frame(), fi, lookup);
  BodyField<double> full(shapes, sub, test::unit_frame(), ff, lookup);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random_vector = [&](double length) {
    Eigen::Vector3d v(u(rng), u(rng), u(rng));
    return v.normalized() * length * 0.5 * (1.0 + u(rng));
  };
  std::vector<Motion> m(3);
  m[0] = {Eigen::Vector3d(9.3, 10.1, 8.7), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  m[1] = {Eigen::Vector3d(26.2, 9.6, 25.1), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  m[2] = {Eigen::Vector3d(17.9, 27.4, 17.2), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  m[2].shape = 1;
  for (std::size_t k = 0; k < m.size(); ++k) {
    m[k].id = static_cast<std::int64_t>(k + 1);
    m[k].q = Eigen::Quaterniond(Eigen::AngleAxisd(0.3 + k, random_vector(1.0).normalized()));
  }
  std::size_t evaluations = 0, scans = 0;
  for (int step = 0; step < 150; ++step) {
    std::vector<BodyState> states;
    for (const Motion& b : m) states.push_back(b.packet());
    update_both(inc, full, fi, ff, states, step, evaluations, scans);
    if (::testing::Test::HasFatalFailure()) return;
    for (Motion& b : m) {
      b.v = random_vector(0.08);
      b.w = random_vector(0.01);
      b.advance();
    }
  }
  std::printf("150 steps of small moves: %zu evaluations, %zu support scans\n", evaluations, scans);
  EXPECT_EQ(scans, 3u);  // the first embeddings only
}

TEST(BandUpdate, SmallRandomMovesEqualFull) {
  small_random_moves_equal_full(PorosityLookup::trilinear);
}

TEST(BandUpdate, SmallRandomMovesEqualFullWithNearestLookup) {
  small_random_moves_equal_full(PorosityLookup::nearest);
}

TEST(BandUpdate, BodiesInContactStayConsistent) {
  // Two cubes sliding past each other with their bands overlapping.
  const Shape s = test::cube(6, 0.5);
  const Subdomain sub = test::whole(24);
  PorousField<double> fi, ff;
  BodyField<double> inc({&s, 1}, sub, test::unit_frame(), fi);
  BodyField<double> full({&s, 1}, sub, test::unit_frame(), ff);
  // Faces 0.8 cells apart along x; b turns about x, which keeps its x faces in place.
  Motion a{Eigen::Vector3d(8.1, 9.2, 12), Eigen::Vector3d(0, 0.2, 0.05), Eigen::Vector3d::Zero()};
  Motion b{Eigen::Vector3d(14.9, 15.2, 12.1), Eigen::Vector3d(0, -0.2, 0),
           Eigen::Vector3d(0.03, 0, 0)};
  a.id = 1;
  b.id = 2;
  int shared = 0;
  for (int step = 0; step < 25; ++step) {
    const BodyState states[2] = {a.packet(), b.packet()};
    const UpdateStats st = inc.update(states);
    EXPECT_EQ(st.interior_conflicts, 0u);
    EXPECT_EQ(st.full_scans, step == 0 ? 2u : 0u);
    full.update(states, UpdateMode::full);
    expect_same_field(fi, ff, step);
    if (HasFatalFailure()) return;
    for (CellIndex c = 0; c < sub.box.cells_with_ghosts(); ++c)
      shared += inc.body_porosity(1, c) < 1.0f && inc.body_porosity(2, c) < 1.0f;
    a.advance();
    b.advance();
  }
  EXPECT_GT(shared, 0);
}

TEST(BandUpdate, CostGrowsWithSurfaceNotVolume) {
  // Evaluations per incremental update for spheres of radius 4, 8, 16 cells: ~R^2.
  std::vector<double> per_update;
  for (double radius : {4.0, 8.0, 16.0}) {
    const Shape s = test::sphere(radius, 0.5);
    const int n = static_cast<int>(2 * radius) + 10;
    const Subdomain sub = test::whole(n);
    PorousField<double> field;
    BodyField<double> bodies({&s, 1}, sub, test::unit_frame(), field);
    Motion m{Eigen::Vector3d(n / 2.0, n / 2.0 + 0.2, n / 2.0 - 0.1),
             Eigen::Vector3d(0.11, -0.07, 0.05), Eigen::Vector3d(0.005, 0.01, 0.0)};
    BodyState st = m.packet();
    // CPU time (not wall time): the test machine is shared, printed for information only.
    const std::clock_t t0 = std::clock();
    const UpdateStats first = bodies.update({&st, 1});
    const std::clock_t t1 = std::clock();
    std::size_t evaluated = 0, band = 0;
    const int steps = 40;
    for (int k = 0; k < steps; ++k) {
      m.advance();
      st = m.packet();
      const UpdateStats stats = bodies.update({&st, 1});
      evaluated += stats.evaluated;
      band += stats.band;
    }
    const std::clock_t t2 = std::clock();
    const double full_us = 1e6 * double(t1 - t0) / CLOCKS_PER_SEC;
    const double inc_us = 1e6 * double(t2 - t1) / CLOCKS_PER_SEC / steps;
    per_update.push_back(double(evaluated) / steps);
    std::printf(
        "R = %4.1f: full embed %7zu evals %8.0f us | incremental %7.0f evals, band %6.0f"
        " cells, %7.0f us per update\n",
        radius, first.evaluated, full_us, per_update.back(), double(band) / steps, inc_us);
  }
  // Doubling R multiplies a surface cost by 4 and a volume cost by 8.
  EXPECT_GT(per_update[2] / per_update[1], 3.0);
  EXPECT_LT(per_update[2] / per_update[1], 5.0);
  EXPECT_LT(per_update[1] / per_update[0], 5.0);
}

}  // namespace
}  // namespace lbdem::hlbm
