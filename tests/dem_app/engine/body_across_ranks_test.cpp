// A long body whose spheres lie on several DEM ranks (the box is split along its length),
// driven by loads that change every run and moving across the rank boundaries: its
// trajectory must match the same run on one rank. Run on 1, 2, 3 and 4 ranks (ctest
// dem_engine_*). Across rank counts LAMMPS sums the spheres' forces into the body in another
// order, so the match is to round-off: relative 1e-12 (measured: about 1e-15).
#include <gtest/gtest.h>

#include <library.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine_support.hpp"

namespace lbdem {
namespace {

// A 60 x 10 x 10 mm rod across a 120 mm box: on 4 ranks each rank holds part of it.
const char* kRod = R"(
name: rod
time: {end: 0.1}
dem:
  gravity: [0, 0, -9.81]
  box: {lo: [0, 0, 0], hi: [0.12, 0.04, 0.04]}
  dt: 1.0e-5
shapes:
  - {name: rod, kind: cuboid, edges: [0.06, 0.01, 0.01]}
bodies:
  - {shape: rod, position: [0.055, 0.02, 0.02], density: 2500, velocity: [5, 0, 0],
     angular_velocity: [3, 0, 40]}
)";

using State = std::array<double, 13>;  // x, v, omega, q

// The body's state from its owner, on every rank of the engine's communicator.
State state_of(const LammpsEngine& e) {
  State s{};
  for (const auto& b : e.owned_states(0)) {
    std::copy(b.x, b.x + 3, s.begin());
    std::copy(b.v, b.v + 3, s.begin() + 3);
    std::copy(b.w, b.w + 3, s.begin() + 6);
    std::copy(b.q, b.q + 4, s.begin() + 9);
  }
  MPI_Allreduce(MPI_IN_PLACE, s.data(), static_cast<int>(s.size()), MPI_DOUBLE, MPI_SUM, e.comm());
  return s;
}

// Runs of 1 to 17 substeps with a load that changes every run (so the first-evaluation
// correction is exercised); the load is set by the last rank after a wrong one from rank 0
// (the last one set wins, in rank order).
std::vector<State> trajectory(MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  DemSetup setup = test::setup_from_scene(test::scene_from_text(kRod), true);
  setup.lammps_log = "none";  // one engine per rank on MPI_COMM_SELF: no shared log file
  LammpsEngine e(comm, setup);
  // The rod starts across x = 25 to 85 mm: its spheres lie on up to three ranks.
  int holders = lammps_extract_setting(e.handle(), "nlocal") > 0 ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &holders, 1, MPI_INT, MPI_SUM, comm);
  EXPECT_EQ(holders, std::min(size, 3));
  const double m = e.body_mass(0);
  std::vector<State> out{state_of(e)};
  for (int k = 0; k < 60; ++k) {
    const double s = std::sin(0.3 * k), c = std::cos(0.2 * k);
    if (rank == 0) e.set_load(0, Eigen::Vector3d(-9, 9, 9) * m, Eigen::Vector3d(1, 1, 1));
    if (rank == size - 1)
      e.set_load(0, Eigen::Vector3d(2 * s, c, 9.81 + s) * m, Eigen::Vector3d(s, c, -s) * 1e-5);
    e.run(1 + 4 * (k % 5));
    out.push_back(state_of(e));
  }
  return out;
}

TEST(Engine, BodyAcrossRanksMatchesOneRank) {
  const std::vector<State> one = trajectory(MPI_COMM_SELF);
  const std::vector<State> many = trajectory(MPI_COMM_WORLD);
  ASSERT_EQ(one.size(), many.size());
  // It crossed rank boundaries: from x = 55 mm by more than 20 mm (the rank planes of 2 to 4 ranks
  // lie 30 to 60 mm apart).
  EXPECT_GT(one.back()[0] - one.front()[0], 0.02);
  double worst = 0;
  for (size_t k = 0; k < one.size(); ++k)
    for (int g = 0; g < 4; ++g) {  // position, velocity, angular velocity, orientation
      const int n = g == 3 ? 4 : 3;
      double scale = 0, diff = 0;
      for (int d = 0; d < n; ++d) {
        scale = std::max(scale, std::abs(one[k][static_cast<size_t>(3 * g + d)]));
        diff = std::max(diff, std::abs(one[k][static_cast<size_t>(3 * g + d)] -
                                       many[k][static_cast<size_t>(3 * g + d)]));
      }
      worst = std::max(worst, diff / scale);
    }
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1)
    EXPECT_EQ(worst, 0.0);  // the same decomposition: bit for bit
  else
    EXPECT_LT(worst, 1e-12);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::printf("body across %d ranks against 1: largest relative difference %.3e\n", size, worst);
}

}  // namespace
}  // namespace lbdem
