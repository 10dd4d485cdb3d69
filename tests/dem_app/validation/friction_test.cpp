// A cube on a floor with gravity tilted by theta (equivalent to an incline): sticks for
// tan(theta) < mu, slides with a = g (sin(theta) - mu cos(theta)) otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "validation_support.hpp"

namespace lbdem {
namespace {

struct Motion {
  std::vector<double> t, x, v;  // samples every 5 ms from 0.1 s (normal bouncing decayed)
  double mu = 0, g = 9.81;
};

// Runs the incline scene at tilt theta (degrees) for 0.3 s.
Motion slide(double theta_deg) {
  DemSetup setup = test::load_setup(test::validation_scene("friction_incline.yaml"));
  const double th = theta_deg * std::numbers::pi / 180.0;
  Motion m;
  setup.params.gravity = {m.g * std::sin(th), 0, -m.g * std::cos(th)};
  m.mu = setup.params.material.friction;
  LammpsEngine engine(MPI_COMM_WORLD, setup);
  const auto to_steps = [&](double t) { return std::lround(t / engine.dt()); };
  engine.run(to_steps(0.1));
  for (int k = 0; k <= 40; ++k) {
    if (k > 0) engine.run(to_steps(0.005));
    const auto s = test::all_states(engine);
    m.t.push_back(engine.time());
    m.x.push_back(s[0].x[0]);
    m.v.push_back(s[0].v[0]);
  }
  return m;
}

// Least-squares slope of y(t): averages out the block's rocking on its contact springs.
double slope(const std::vector<double>& t, const std::vector<double>& y) {
  double st = 0, sy = 0, stt = 0, sty = 0;
  const double n = static_cast<double>(t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    st += t[i];
    sy += y[i];
    stt += t[i] * t[i];
    sty += t[i] * y[i];
  }
  return (n * sty - st * sy) / (n * stt - st * st);
}

TEST(Friction, SticksBelowFrictionAngle) {
  for (double theta : {20.0, 28.0}) {  // atan(0.6) = 30.96 degrees
    test::WallTimer timer;
    const Motion m = slide(theta);
    // The stuck block rocks on its tangential (Mindlin) springs, lightly damped: +-2e-5 m,
    // +-1e-3 m/s here. Sliding at 35 degrees would move it by 0.02 m in the same 0.2 s.
    const double drift = std::abs(m.x.back() - m.x.front());
    char name[64];
    std::snprintf(name, sizeof name, "friction stick theta=%.0f deg", theta);
    test::report(name, "drift over 0.2 s (m), absolute", drift, 5e-5, timer.seconds());
    EXPECT_LT(drift, 5e-5) << theta;
    EXPECT_LT(std::abs(slope(m.t, m.x)), 1e-4) << theta;  // mean speed, m/s
  }
}

TEST(Friction, SlidesWithCoulombAccelerationAbove) {
  for (double theta : {35.0, 42.0}) {
    test::WallTimer timer;
    const Motion m = slide(theta);
    const double th = theta * std::numbers::pi / 180.0;
    const double expected = m.g * (std::sin(th) - m.mu * std::cos(th));
    const double measured = slope(m.t, m.v);
    const double error = std::abs(measured - expected) / expected;
    char name[64], what[96];
    std::snprintf(name, sizeof name, "friction slide theta=%.0f deg", theta);
    std::snprintf(what, sizeof what, "a = %.4f m/s^2 vs g(sin - mu cos) = %.4f, relative", measured,
                  expected);
    test::report(name, what, error, 1e-2, timer.seconds());
    EXPECT_LT(error, 1e-2) << theta;
  }
}

}  // namespace
}  // namespace lbdem
