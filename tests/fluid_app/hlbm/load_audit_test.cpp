// Momentum audits of the hydrodynamic loads on the real solver (docs/method-loads.md).
//
// (a) A body towed at constant velocity, or spinning at a constant rate, through a triply
//     periodic box with no other force: the momentum (angular momentum) the fluid outside the
//     bodies gains, J - sum Q, must equal minus the impulse (angular impulse) reported to the
//     body. R = 3, 6, 9 cells, Re = 2 and 20, sphere and volume-equivalent cube. The
//     momentum-exchange ratio of the same runs is printed for comparison.
// (c) Bodies at rest in fluid at rest, alone and with overlapping bands: no load.
#include <gtest/gtest.h>
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "fluid_app/coupling/solver_binding.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"
#include "tests/fluid_app/hlbm/hlbm_fixtures.hpp"

namespace lbdem::hlbm {
namespace {

constexpr double kTau = 0.6;

// Lattice linear and angular momentum (about `centre`, minimum image) of the post-stream
// populations, minus what the bodies cover (Q, L of the last step).
struct Momenta {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
};

Momenta outside_fluid(const FluidSolver<double>& s, const Subdomain& sub,
                      const Eigen::Vector3d& centre) {
  Momenta m;
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const CellIndex c = b.index(x, y, z);
        Eigen::Vector3d j = Eigen::Vector3d::Zero();
        for (int i = 1; i < d3q19::Q; ++i)
          for (int a = 0; a < 3; ++a) j[a] += d3q19::c[i][a] * s.population(i, c);
        const Eigen::Vector3d r(sub.min_image(0, sub.position(0, x) - centre[0]),
                                sub.min_image(1, sub.position(1, y) - centre[1]),
                                sub.min_image(2, sub.position(2, z) - centre[2]));
        m.p += j;
        m.l += r.cross(j);
      }
  if (s.porous().active)
    for (const PenaltyExchange& e : s.porous().exchange)
      for (int a = 0; a < 3; ++a) {
        m.p[a] -= e.covered[a];
        m.l[a] -= e.covered_moment[a];
      }
  return m;
}

enum class Motion { towed, spinning };

struct AuditResult {
  double error = 0;     // |fluid gain + reported impulse| / |reported impulse|: the whole
                        // vector, so a load that lost a component fails
  double ratio_me = 0;  // fluid gain . -(impulse) / |impulse|^2 with the momentum exchange's
                        // loads, printed for comparison
  double wall_s = 0;
};

// Radius R in cells; the cube has the sphere's volume.
AuditResult audit(Motion motion, bool cube, double radius, double reynolds) {
  const auto t0 = std::chrono::steady_clock::now();
  const double nu = (kTau - 0.5) / 3.0;
  // Populations move at most one cell per step: with the box edge 2 (R + 3 + steps) nothing
  // the body starts reaches the periodic seam of the minimum image around it, where the
  // angular momentum of a periodic lattice is not conserved.
  const int steps = 24;
  const int n = 2 * (static_cast<int>(std::ceil(radius)) + 3 + steps);
  const FluidParams p = testing_fluid::lattice_params(n, n, n, kTau);
  FluidSolver<double> s(p, MPI_COMM_SELF);
  const Shape shape = cube ? test::cube(2 * radius * std::cbrt(std::numbers::pi / 6), 0.5)
                           : test::sphere(radius, 0.5);
  const Subdomain sub = subdomain_of(s, p);
  BodyField<double> bodies({&shape, 1}, sub, {Eigen::Vector3d::Zero(), p.units}, s.porous());
  PenaltyLoads<double> loads;
  // Re = U 2R / nu with U the speed (towed) or the equator speed (spinning).
  const double speed = reynolds * nu / (2 * radius);
  const bool towed = motion == Motion::towed;
  const Eigen::Vector3d v = Eigen::Vector3d(0.8, 0.5, 0.33).normalized() * (towed ? speed : 0.0);
  const Eigen::Vector3d w =
      Eigen::Vector3d(0.3, -0.5, 0.81).normalized() * (towed ? 0.0 : speed / radius);
  const Eigen::Vector3d x0 = Eigen::Vector3d::Constant(n / 2.0 + 0.23);

  const Momenta start = outside_fluid(s, sub, x0);
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero(), angular = Eigen::Vector3d::Zero();
  Eigen::Vector3d impulse_me = Eigen::Vector3d::Zero(), angular_me = Eigen::Vector3d::Zero();
  for (int k = 0; k < steps; ++k) {
    const Eigen::Vector3d x = x0 + v * k;
    const BodyState st = test::moving_state(x, v, w, k, p.units);
    bodies.update({&st, 1});
    s.step();
    const BodyLoad me = momentum_exchange(bodies, populations_of(s), k).at(0);
    const BodyLoad l = loads.loads(bodies, k).at(0);
    for (int a = 0; a < 3; ++a) {
      impulse[a] += l.f[a] / p.units.force();
      angular[a] += l.t[a] / p.units.torque();
      impulse_me[a] += me.f[a] / p.units.force();
      angular_me[a] += me.t[a] / p.units.torque();
    }
  }
  const Momenta end = outside_fluid(s, sub, x0);
  AuditResult r;
  if (motion == Motion::towed) {
    const Eigen::Vector3d gain = end.p - start.p;
    r.error = (gain + impulse).norm() / impulse.norm();
    r.ratio_me = gain.dot(-impulse_me) / impulse_me.squaredNorm();
  } else {
    const Eigen::Vector3d gain = end.l - start.l;
    r.error = (gain + angular).norm() / angular.norm();
    r.ratio_me = gain.dot(-angular_me) / angular_me.squaredNorm();
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void run_audits(Motion motion, bool cube) {
  for (double radius : {3.0, 6.0, 9.0})
    for (double re : {2.0, 20.0}) {
      const AuditResult r = audit(motion, cube, radius, re);
      std::printf(
          "%s %s R = %.0f Re = %.0f: |fluid gain + reported| / |reported| = %.1e; momentum "
          "exchange's gain / reported: %.4f; %.2f s\n",
          cube ? "cube" : "sphere", motion == Motion::towed ? "towed" : "spinning", radius, re,
          r.error, r.ratio_me, r.wall_s);
      // Exact by construction: only round-off may remain, in every component.
      EXPECT_LT(r.error, 1e-9) << "R = " << radius << ", Re = " << re;
    }
}

TEST(LoadAudit, TowedSphereMomentumBalances) {
  run_audits(Motion::towed, false);
}
TEST(LoadAudit, TowedCubeMomentumBalances) {
  run_audits(Motion::towed, true);
}
TEST(LoadAudit, SpinningSphereAngularMomentumBalances) {
  run_audits(Motion::spinning, false);
}
TEST(LoadAudit, SpinningCubeAngularMomentumBalances) {
  run_audits(Motion::spinning, true);
}

// (c) Bodies at rest in fluid at rest: alone, and a cube whose corner comes within a cell of
// a sphere (overlapping bands, cells changing owner by the two-body rule).
TEST(LoadAudit, BodiesAtRestInFluidAtRestFeelNoLoad) {
  const FluidParams p = testing_fluid::lattice_params(30, 28, 26, kTau);
  const Shape shapes[2] = {test::cube(7, 0.5), test::sphere(4, 0.5)};
  for (bool pair : {false, true}) {
    FluidSolver<double> s(p, MPI_COMM_SELF);
    BodyField<double> bodies(shapes, subdomain_of(s, p), {Eigen::Vector3d::Zero(), p.units},
                             s.porous());
    PenaltyLoads<double> loads;
    std::vector<BodyState> st = {test::state(
        0, Eigen::Vector3d(10.3, 12.1, 13.2) * p.dx,
        Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized())))};
    if (pair)
      st.push_back(test::state(1, Eigen::Vector3d(17.6, 14.9, 13.4) * p.dx, {1, 0, 0, 0},
                               Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 1));
    bodies.update(st);
    double worst = 0;
    for (int k = 0; k < 20; ++k) {
      s.step();
      for (const BodyLoad& l : loads.loads(bodies, k))
        for (int a = 0; a < 3; ++a)
          worst = std::max(
              {worst, std::abs(l.f[a]) / p.units.force(), std::abs(l.t[a]) / p.units.torque()});
      bodies.update(st);
    }
    std::printf("%s at rest: largest load component %.1e (lattice units)\n",
                pair ? "cube and sphere with overlapping bands" : "cube alone", worst);
    EXPECT_LT(worst, 1e-12);  // rest populations w_i sum to j ~ 1e-17 per cell
  }
}

}  // namespace
}  // namespace lbdem::hlbm
