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
#include <utility>

#include "dem_app/lubrication/lubrication_law.hpp"
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

// A sphere sliding along the wall at a fixed gap inside h_c, released without spin: with only
// the correction acting, m dU/dt = -A U + B W and I dW/dt = B U - C W (U along x, W the spin
// about y, wall below; lubrication_law.hpp), a linear system solved here in closed form. The
// coupling spins the sphere up in the rolling sense while both decay.
// X' = K X for X = (U, W) released from (u0, 0), in closed form:
// exp(K t) = e^{tau t} [cosh(d t) + sinh(d t) / d (K - tau)], tau = tr K / 2.
struct SlidingSolution {
  double k11, k12, k21, k22;
  // (U, W) at time t.
  std::pair<double, double> at(double t, double u0) const {
    const double tau = 0.5 * (k11 + k22);
    const double d = std::sqrt(0.25 * (k11 - k22) * (k11 - k22) + k12 * k21);
    const double e = std::exp(tau * t), ch = std::cosh(d * t), sh = std::sinh(d * t) / d;
    return {e * (ch + sh * (k11 - tau)) * u0, e * sh * k21 * u0};
  }
};

TEST(Lubrication, SphereSlidingAlongAWallFollowsTheResistanceMatrix) {
  test::WallTimer timer;
  DemSetup setup = test::load_setup(scene());
  const LubricationLaw law{setup.params.lubrication.viscosity, setup.params.lubrication.cutoff,
                           setup.params.lubrication.min_gap};
  const double u0 = 0.01, h0 = 1e-4;
  setup.bodies.resize(1);
  setup.bodies[0].position = {0.02, 0.05, kRadius + h0};
  setup.bodies[0].velocity = {u0, 0, 0};
  LammpsEngine engine(MPI_COMM_WORLD, setup);
  const SlidingResistance r = wall_sliding_resistance(law, kRadius, h0);
  const double m = mass(), inertia = 0.4 * m * kRadius * kRadius;
  const SlidingSolution exact{-r.translation / m, r.coupling / m, r.coupling / inertia,
                              -r.rotation / inertia};
  double worst = 0, drift = 0, spin = 0;
  const double dt = setup.params.dt;
  for (long step = 20; step <= 30000; step += 20) {
    engine.run(20);
    const auto s = test::all_states(engine);
    const double t = step * dt;
    const auto [u, w] = exact.at(t, u0);
    worst = std::max({worst, std::abs(s[0].v[0] - u) / u0, std::abs(s[0].w[1] - w) * kRadius / u0});
    drift = std::max({drift, std::abs(s[0].x[2] - kRadius - h0) / h0, std::abs(s[0].v[1]) / u0});
    spin = s[0].w[1] * kRadius / s[0].v[0];
  }
  char what[160];
  std::snprintf(what, sizeof what,
                "U and a W vs the closed form %.2e of U0; gap and cross drift %.1e; a W / U at "
                "0.3 s %.3f,",
                worst, drift, spin);
  test::report("lubrication sphere sliding on a wall (DEM only)", what, worst, 2e-3,
               timer.seconds());
  EXPECT_LT(worst, 2e-3);
  EXPECT_LT(drift, 1e-9);
  EXPECT_GT(spin, 0.1);  // spun up in the rolling sense
}

// Two equal spheres sliding past each other at a fixed gap inside h_c (sphere 1 at -x moving
// +z, sphere 2 at +x moving -z, no spin; on two ranks they lie on different ones), only the
// correction acting. By symmetry both spin alike, w1 = w2 = -W about y, and with U the speed of
// each (du = 2U), the pair's resistances (lubrication_law.hpp) give m dU/dt = -2a U + 2b W and
// I dW/dt = 2b U - (c11 + c12) W, the same linear system as the wall's, solved in closed form.
// The speed is kept so small (1e-5 m/s) that the sliding changes the gap by 1e-6 of itself.
// Angular momentum about the pair's centre, sum I w + m (x - c) x v, stays at its start.
TEST(Lubrication, TwoSpheresSlidingPastEachOtherFollowTheResistanceMatrix) {
  test::WallTimer timer;
  DemSetup setup = test::load_setup(scene());
  const LubricationLaw law{setup.params.lubrication.viscosity, setup.params.lubrication.cutoff,
                           setup.params.lubrication.min_gap};
  const double u0 = 1e-5, h0 = 1e-4, c = 0.05;
  setup.bodies[0].position = {c - kRadius - 0.5 * h0, c, c};
  setup.bodies[1].position = {c + kRadius + 0.5 * h0, c, c};
  setup.bodies[0].velocity = {0, 0, u0};
  setup.bodies[1].velocity = {0, 0, -u0};
  LammpsEngine engine(MPI_COMM_WORLD, setup);
  const PairSlidingResistance r = pair_sliding_resistance(law, kRadius, kRadius, h0);
  const double m = mass(), inertia = 0.4 * m * kRadius * kRadius;
  const SlidingSolution exact{-2 * r.translation / m, 2 * r.coupling1 / m,
                              2 * r.coupling1 / inertia, -(r.rotation11 + r.rotation12) / inertia};
  const double r0 = 2 * kRadius + h0, l0 = m * r0 * u0;  // angular momentum about y at start
  double worst = 0, drift = 0, cross = 0, spin = 0, momentum = 0;
  const double dt = setup.params.dt;
  for (long step = 100; step <= 30000; step += 100) {
    engine.run(100);
    const auto s = test::all_states(engine);
    const double t = step * dt;
    const auto [u, w] = exact.at(t, u0);
    for (int b = 0; b < 2; ++b) {
      const double sign = b == 0 ? 1 : -1;
      worst = std::max(
          {worst, std::abs(sign * s[b].v[2] - u) / u0, std::abs(-s[b].w[1] - w) * kRadius / u0});
      cross = std::max(cross, std::abs(s[b].v[1]) / u0);
    }
    // The sliding pair separates slowly (geometry: r grows like dx^2 / 2r); the gap, from the
    // centre distance, must stay at h0 within that.
    double r2 = 0;
    for (int k = 0; k < 3; ++k) r2 += (s[1].x[k] - s[0].x[k]) * (s[1].x[k] - s[0].x[k]);
    drift = std::max(drift, std::abs(std::sqrt(r2) - 2 * kRadius - h0) / h0);
    // L_y = sum I w_y + m (z - c) v_x - m (x - c) v_z, about the start's centre.
    double ly = 0;
    for (int b = 0; b < 2; ++b)
      ly += inertia * s[b].w[1] + m * ((s[b].x[2] - c) * s[b].v[0] - (s[b].x[0] - c) * s[b].v[2]);
    momentum = std::max(momentum, std::abs(ly - l0) / std::abs(l0));
    spin = -s[0].w[1] * kRadius / s[0].v[2];
  }
  char what[200];
  std::snprintf(what, sizeof what,
                "U and a W vs the closed form %.2e of U0; gap drift %.1e; cross speed %.1e; "
                "angular momentum %.1e; a W / U at 0.3 s %.3f,",
                worst, drift, cross, momentum, spin);
  test::report("lubrication spheres sliding past each other (DEM only)", what, worst, 2e-3,
               timer.seconds());
  EXPECT_LT(worst, 2e-3);
  EXPECT_LT(drift, 1e-4);
  EXPECT_LT(cross, 1e-9);
  EXPECT_LT(momentum, 1e-9);
  EXPECT_LT(spin, -0.05);  // spun in the sense of rolling on the other sphere
}

}  // namespace
}  // namespace lbdem
