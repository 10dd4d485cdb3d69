#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine_support.hpp"

namespace lbdem {
namespace {

const char* kDrop = R"(
name: drop
time: {end: 0.1}
dem:
  gravity: [0, 0, -9.81]
  box: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}
  dt: 1.0e-5
  walls: [{axis: z, side: lo}]
shapes:
  - {name: ball, kind: sphere, diameter: 0.01}
bodies:
  - {shape: ball, position: [0.05, 0.05, 0.05], density: 2500, velocity: [0.1, 0, 0]}
)";

// Free fall before touching the floor: x = x0 + v0 t, z = z0 - g t^2 / 2, exactly (the
// integrator is exact for constant acceleration).
TEST(Engine, FreeFallOfOneSphereIsExact) {
  LammpsEngine e(MPI_COMM_WORLD, test::setup_from_scene(test::scene_from_text(kDrop)));
  e.run(5000);  // 0.05 s: falls 12 mm, still 33 mm above the floor
  const double t = e.time();
  EXPECT_NEAR(t, 0.05, 1e-12);
  double z = 0, x = 0, vz = 0;
  int found = 0;
  for (const auto& s : e.owned_states(0)) {
    z = s.x[2];
    x = s.x[0];
    vz = s.v[2];
    found = 1;
  }
  int total = 0;
  MPI_Allreduce(&found, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, 1);
  if (found) {
    EXPECT_NEAR(x, 0.05 + 0.1 * t, 1e-12);
    EXPECT_NEAR(z, 0.05 - 0.5 * 9.81 * t * t, 1e-12);
    EXPECT_NEAR(vz, -9.81 * t, 1e-12);
  }
}

// DEM-only buoyancy: gravity on the body mass plus -rho_f V g through the external-load path
// gives the reduced acceleration g (1 - rho_f / rho_b), again exactly.
TEST(Engine, BuoyancyReducesGravityExactly) {
  std::string text = kDrop;
  text.replace(text.find("  dt: 1.0e-5"), 0, "  buoyancy_fluid_density: 1000\n");
  LammpsEngine e(MPI_COMM_WORLD, test::setup_from_scene(test::scene_from_text(text)));
  e.run(5000);
  const double t = e.time(), g = 9.81 * (1.0 - 1000.0 / 2500.0);
  // Checked on the rank that owns the body; exactly one rank must own it.
  int found = 0;
  for (const auto& s : e.owned_states(0)) {
    EXPECT_NEAR(s.x[2], 0.05 - 0.5 * g * t * t, 1e-12);
    EXPECT_NEAR(s.v[2], -g * t, 1e-12);
    ++found;
  }
  int total = 0;
  MPI_Allreduce(&found, &total, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(total, 1);
}

}  // namespace
}  // namespace lbdem
