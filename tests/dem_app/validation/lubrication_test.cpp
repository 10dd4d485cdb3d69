// The lubrication correction inside the DEM steps, with no fluid: a sphere approaching a wall
// and two spheres approaching each other inside the cut-off gap. With only the correction
// acting, m_r dw = -c(h) dh (w the approach velocity, m_r the reduced mass), so the speed at
// every gap is w(h) = w0 + (1/m_r) int_h^h0 c dh' and the bodies stop at the gap h* where that
// integral equals m_r |w0|. The integral is done here by Simpson's rule on the law itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "dem_app/lubrication_law.hpp"
#include "validation_support.hpp"

namespace lbdem {
namespace {

const double kRadius = 0.005, kDensity = 2500;

std::string scene() {
  return std::string(LBDEM_SOURCE_DIR) + "/configs/validation/lubrication/dem_squeeze.yaml";
}

double mass() {
  return kDensity * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
}

// int_h^h0 c(h') dh' (Simpson, on a log-spaced grid: c varies like 1/h).
double impulse(const LubricationLaw& law, double a2, double h, double h0) {
  const int n = 2000;
  const double l0 = std::log(h), l1 = std::log(h0), dl = (l1 - l0) / n;
  double s = 0;
  for (int k = 0; k <= n; ++k) {
    const double x = std::exp(l0 + k * dl);
    const double w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    s += w * lubrication_resistance(law, kRadius, a2, x) * x;  // dh = h dl
  }
  return s * dl / 3;
}

struct Trace {
  double worst = 0;      // largest |w - w_analytic| / |w0| over the approach
  double final_gap = 0;  // where the approach stopped
  double momentum = 0;   // largest |m (v1 + v2)| / (m |w0|) (two spheres)
};

// Runs until the approach speed has fallen below 1e-4 of its start.
Trace run_approach(bool wall, double w0, double h0) {
  DemSetup setup = test::load_setup(scene());
  const LubricationLaw law{setup.params.lubrication.viscosity, setup.params.lubrication.cutoff,
                           setup.params.lubrication.min_gap};
  if (wall) {
    setup.bodies.resize(1);
    setup.bodies[0].position = {0.05, 0.05, kRadius + h0};
    setup.bodies[0].velocity = {0, 0, -w0};
  } else {
    setup.bodies[0].position = {0.05 - kRadius - 0.5 * h0, 0.05, 0.05};
    setup.bodies[1].position = {0.05 + kRadius + 0.5 * h0, 0.05, 0.05};
    setup.bodies[0].velocity = {0.5 * w0, 0, 0};
    setup.bodies[1].velocity = {-0.5 * w0, 0, 0};
  }
  LammpsEngine engine(MPI_COMM_WORLD, setup);
  const double m_r = wall ? mass() : 0.5 * mass();
  Trace t;
  for (long step = 0; step < 400000; step += 20) {
    engine.run(20);
    const auto s = test::all_states(engine);
    const double gap = wall ? s[0].x[2] - kRadius : s[1].x[0] - s[0].x[0] - 2 * kRadius;
    const double w = wall ? -s[0].v[2] : s[0].v[0] - s[1].v[0];
    const double expected = w0 - impulse(law, wall ? 0.0 : kRadius, gap, h0) / m_r;
    t.worst = std::max(t.worst, std::abs(w - expected) / w0);
    if (!wall) t.momentum = std::max(t.momentum, std::abs(s[0].v[0] + s[1].v[0]) / w0);
    t.final_gap = gap;
    if (w < 1e-4 * w0) break;
  }
  return t;
}

// The gap where the approach stops: int_h*^h0 c = m_r w0 (bisection in log h).
double stop_gap(double a2, double m_r, double w0, double h0) {
  DemSetup setup = test::load_setup(scene());
  const LubricationLaw law{setup.params.lubrication.viscosity, setup.params.lubrication.cutoff,
                           setup.params.lubrication.min_gap};
  double lo = law.min_gap, hi = h0;
  for (int k = 0; k < 100; ++k) {
    const double mid = std::sqrt(lo * hi);
    (impulse(law, a2, mid, h0) > m_r * w0 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

TEST(Lubrication, SphereApproachingAWallFollowsTheMomentumBalance) {
  test::WallTimer timer;
  const double w0 = 0.02, h0 = 0.9e-3;
  const Trace t = run_approach(true, w0, h0);
  const double h_stop = stop_gap(0.0, mass(), w0, h0);
  const double stop_error = std::abs(t.final_gap - h_stop) / h_stop;
  char what[128];
  std::snprintf(what, sizeof what, "speed vs momentum balance %.2e of w0; stop gap %.4e m vs %.4e,",
                t.worst, t.final_gap, h_stop);
  test::report("lubrication sphere-wall (DEM only)", what, stop_error, 1e-2, timer.seconds());
  // Velocity Verlet with the half-step speed in the damper: first order in dt c/m (<= 0.03 here).
  EXPECT_LT(t.worst, 2e-3);
  EXPECT_LT(stop_error, 1e-2);
}

TEST(Lubrication, TwoSpheresApproachingFollowTheMomentumBalanceAndConserveMomentum) {
  test::WallTimer timer;
  const double w0 = 0.02, h0 = 0.9e-3;
  const Trace t = run_approach(false, w0, h0);
  const double h_stop = stop_gap(kRadius, 0.5 * mass(), w0, h0);
  const double stop_error = std::abs(t.final_gap - h_stop) / h_stop;
  char what[160];
  std::snprintf(what, sizeof what,
                "speed vs momentum balance %.2e of w0; momentum %.1e; stop gap %.4e m vs %.4e,",
                t.worst, t.momentum, t.final_gap, h_stop);
  test::report("lubrication sphere-sphere (DEM only)", what, stop_error, 1e-2, timer.seconds());
  EXPECT_LT(t.worst, 2e-3);
  EXPECT_LT(stop_error, 1e-2);
  EXPECT_LT(t.momentum, 1e-12);
}

}  // namespace
}  // namespace lbdem
