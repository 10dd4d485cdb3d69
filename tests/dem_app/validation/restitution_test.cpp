// Binary collision of two equal spheres: the measured restitution must match the requested
// one (the restitution map of dem_app/contact/restitution_map.hpp, through LAMMPS's damping tsuji).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "validation_support.hpp"

namespace lbdem {
namespace {

struct Case {
  double e;
  double speed;        // approach speed, m/s
  double dt_fraction;  // of the Rayleigh time
  double tolerance;    // relative
};

class Restitution : public ::testing::TestWithParam<Case> {};

TEST_P(Restitution, MeasuredMatchesRequested) {
  const Case c = GetParam();
  test::WallTimer timer;
  DemSetup setup = test::load_setup(test::validation_scene("restitution.yaml"));
  setup.params.material.restitution = c.e;
  setup.params.dt_fraction = c.dt_fraction;
  const double r = 0.5 * 0.01, gap = 0.001;
  setup.bodies[0].position = {0.05 - r - 0.5 * gap, 0.05, 0.05};
  setup.bodies[1].position = {0.05 + r + 0.5 * gap, 0.05, 0.05};
  setup.bodies[0].velocity = {0.5 * c.speed, 0, 0};
  setup.bodies[1].velocity = {-0.5 * c.speed, 0, 0};
  LammpsEngine engine(MPI_COMM_WORLD, setup);

  // Until the spheres are apart again and receding (a contact lasts ~ 10 ms here).
  const long chunk = 10;
  double e_measured = 0;
  for (long steps = 0; steps < 200000; steps += chunk) {
    engine.run(chunk);
    const auto s = test::all_states(engine);
    const double distance = s[1].x[0] - s[0].x[0];
    const double separation_speed = s[1].v[0] - s[0].v[0];
    if (separation_speed > 0 && distance > 2 * r) {
      e_measured = separation_speed / c.speed;
      break;
    }
  }
  const double error = std::abs(e_measured - c.e) / c.e;
  char name[64], what[64];
  std::snprintf(name, sizeof name, "restitution e=%.2f v=%.2f m/s dt=%.2f t_R", c.e, c.speed,
                c.dt_fraction);
  std::snprintf(what, sizeof what, "measured e %.5f, relative", e_measured);
  test::report(name, what, error, c.tolerance, timer.seconds());
  // The map is exact for the continuous Hertz-Tsuji law; what remains is the time
  // discretization of the contact: up to 0.8 % at the paper's dt = 0.05 t_R (a contact then
  // lasts ~30-60 steps), below 0.2 % at 0.01 t_R, 0.05 % at 0.002 t_R (measured). Tolerances
  // 1.2 % and 0.2 %: 1.5x and 2x the largest error at each step (docs/testing.md).
  EXPECT_LT(error, c.tolerance);
}

INSTANTIATE_TEST_SUITE_P(Dem, Restitution,
                         ::testing::Values(Case{0.5, 0.05, 0.05, 1.2e-2}, Case{0.5, 0.2, 0.05, 1.2e-2},
                                           Case{0.5, 1.0, 0.05, 1.2e-2}, Case{0.9, 0.05, 0.05, 1.2e-2},
                                           Case{0.9, 0.2, 0.05, 1.2e-2}, Case{0.9, 1.0, 0.05, 1.2e-2},
                                           Case{0.5, 0.05, 0.01, 2e-3}, Case{0.5, 1.0, 0.01, 2e-3},
                                           Case{0.9, 0.05, 0.01, 2e-3}, Case{0.9, 1.0, 0.01, 2e-3}),
                         [](const auto& p) {
                           char name[32];
                           std::snprintf(name, sizeof name, "e%02d_v%03d_dt%03d",
                                         static_cast<int>(p.param.e * 10),
                                         static_cast<int>(p.param.speed * 100),
                                         static_cast<int>(p.param.dt_fraction * 1000));
                           return std::string(name);
                         });

}  // namespace
}  // namespace lbdem
