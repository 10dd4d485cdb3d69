// The covered-fluid term of the penalization load, checked against what it stands for
// (docs/method-loads.md section 2): F = -P + (Q^n - Q^{n-1}) with Q the momentum of the fluid
// the body covers, Q = sum (1 - d) rho u+, and L = sum (1 - d) r x rho u+ for the torque. The
// momentum audits cannot see an error in Q (it enters the fluid's and the body's side alike
// and cancels); here Q is compared with the rigid motion of the fluid inside the body:
//   * field: sum (1 - d) rho u_p(x) with the same field d, rho and the body's rigid velocity
//     u_p = v + w x r: differs from Q only where the band's fluid lags the body (0 < d < 1);
//   * closed form: rho_0 V v and rho_0 I w for the body's own volume V (4/3 pi R^3, a^3) and
//     inertia (8/15 pi R^5, a^5 / 6), independent of the field;
//   * accelerating body: Q^n - Q^{n-1}, the part of the load that accelerates the covered
//     fluid, against rho_0 V a.
// The static counterpart, the steady load against the link-wise momentum exchange on the same
// body, is LatticeCoupling.StokesDragOfPeriodicSphereArrayCoarse (F = g L^3 and
// F_ME = g L^3 (1 - phi): the difference is the force on the covered fluid).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "fluid_app/coupling/solver_binding.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"
#include "tests/fluid_app/hlbm/hlbm_fixtures.hpp"

namespace lbdem::hlbm {
namespace {

constexpr double kTau = 0.8;

enum class Motion { towed, spinning, accelerating };

struct Body {
  std::string name;
  Shape shape;
  double volume = 0;   // cells^3, closed form
  double inertia = 0;  // cells^5 per unit density (isotropic for both shapes), closed form
};

Body sphere(double r) {
  return {"sphere", test::sphere(r, 0.5), 4.0 / 3.0 * std::numbers::pi * r * r * r,
          8.0 / 15.0 * std::numbers::pi * std::pow(r, 5)};
}
Body cube(double a) {
  return {"cube", test::cube(a, 0.5), a * a * a, std::pow(a, 5) / 6.0};
}

struct Covered {
  Eigen::Vector3d q = Eigen::Vector3d::Zero();      // the solver's Q (or L)
  Eigen::Vector3d rigid = Eigen::Vector3d::Zero();  // sum (1 - d) rho u_p (or r x rho u_p)
  double mass = 0;                                  // sum (1 - d) rho
};

// The fluid the body covers in the step just taken, from the solver's sums and, independently,
// from the field d, the density and the rigid velocity.
Covered covered(const FluidSolver<double>& s, const Subdomain& sub, const Eigen::Vector3d& x,
                const Eigen::Vector3d& v, const Eigen::Vector3d& w, bool angular) {
  Covered c;
  const auto& field = s.porous();
  const PenaltyExchange& e = field.exchange.at(0);
  for (int a = 0; a < 3; ++a) c.q[a] = angular ? e.covered_moment[a] : e.covered[a];
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int i = 1; i <= b.n[0]; ++i) {
        const CellIndex cell = b.index(i, y, z);
        const double solid = 1.0 - field.d[static_cast<std::size_t>(cell)];
        if (solid == 0) continue;
        const Eigen::Vector3d r(sub.min_image(0, sub.position(0, i) - x[0]),
                                sub.min_image(1, sub.position(1, y) - x[1]),
                                sub.min_image(2, sub.position(2, z) - x[2]));
        const double m = solid * s.density(cell);
        const Eigen::Vector3d up = v + w.cross(r);
        c.rigid += angular ? Eigen::Vector3d(r.cross(m * up)) : Eigen::Vector3d(m * up);
        c.mass += m;
      }
  return c;
}

struct Errors {
  double field = 0;   // |Q - sum (1 - d) rho u_p| / |that|
  double closed = 0;  // |Q - rho_0 V v| / |rho_0 V v| (or the rate for the accelerating body)
  double volume = 0;  // sum (1 - d) rho / (rho_0 V) - 1
};

// The body moves (towed at constant v, spun at constant w, or accelerated at constant a from
// rest) from the first step; the figures are read after `steps` steps.
Errors measure(const Body& body, Motion motion, int steps) {
  const int n = 2 * static_cast<int>(std::ceil(body.shape.bounding_radius)) + 12;
  const FluidParams p = testing_fluid::lattice_params(n, n, n, kTau);
  FluidSolver<double> s(p, MPI_COMM_SELF);
  const Subdomain sub = subdomain_of(s, p);
  BodyField<double> bodies({&body.shape, 1}, sub, {Eigen::Vector3d::Zero(), p.units}, s.porous());
  PenaltyLoads<double> loads;
  const Eigen::Vector3d dir = Eigen::Vector3d(0.8, 0.5, 0.33).normalized();
  const double speed = 0.02;  // lattice units (towed: v; spinning: at the bounding radius)
  const double accel = speed / steps;
  const Eigen::Vector3d x0 = Eigen::Vector3d::Constant(n / 2.0 + 0.23);
  Eigen::Vector3d previous_q = Eigen::Vector3d::Zero(), x = x0, v, w = Eigen::Vector3d::Zero();
  Errors err;
  for (int k = 0; k < steps; ++k) {
    v = motion == Motion::towed          ? Eigen::Vector3d(dir * speed)
        : motion == Motion::accelerating ? Eigen::Vector3d(dir * accel * (k + 1))
                                         : Eigen::Vector3d::Zero();
    if (motion == Motion::spinning) w = dir * (speed / body.shape.bounding_radius);
    const BodyState st = test::moving_state(x, v, w, k, p.units);
    bodies.update({&st, 1});
    s.step();
    loads.loads(bodies, k);
    const bool angular = motion == Motion::spinning;
    const Covered c = covered(s, sub, x, v, w, angular);
    err.field = (c.q - c.rigid).norm() / c.rigid.norm();
    err.volume = c.mass / body.volume - 1;
    if (motion == Motion::spinning) {
      err.closed = (c.q - body.inertia * w).norm() / (body.inertia * w).norm();
    } else if (motion == Motion::towed) {
      err.closed = (c.q - body.volume * v).norm() / (body.volume * v).norm();
    } else {
      // Q^n - Q^{n-1}, the covered fluid's share of the load, against rho_0 V a.
      const Eigen::Vector3d rate = body.volume * accel * dir;
      err.closed = (c.q - previous_q - rate).norm() / rate.norm();
    }
    previous_q = c.q;
    x += v;
  }
  return err;
}

void check(const Body& body, Motion motion, double field_tol, double closed_tol) {
  const int steps = 20;
  const Errors e = measure(body, motion, steps);
  const char* what = motion == Motion::towed      ? "towed: Q against rho_0 V v"
                     : motion == Motion::spinning ? "spinning: L against rho_0 I w"
                                                  : "accelerated: Q^n - Q^{n-1} against rho_0 V a";
  std::printf(
      "%s %s %.2e (bound %.2f); against the field's rigid covered fluid %.2e (bound %.2f); "
      "covered mass / rho_0 V - 1 = %+.4f; after %d steps\n",
      body.name.c_str(), what, e.closed, closed_tol, e.field, field_tol, e.volume, steps);
  EXPECT_LT(e.field, field_tol);
  EXPECT_LT(e.closed, closed_tol);
  // The field embeds the body's volume: measured within 0.44 % (sphere R 6), 0.02 % (cube).
  EXPECT_LT(std::abs(e.volume), 0.008);
}

// Sphere R = 6 cells and a cube of edge 10 (a whole number of voxels: its volume is exact),
// tau 0.8, lattice speed 0.02, 20 steps. The band's fluid lags the body, so Q reads a few
// per cent below the rigid motion; bounds about 1.7x the measurement (docs/testing.md).
// Towed, measured: against rho_0 V v 2.52e-2 / 2.35e-2, against the field 2.11e-2 / 2.35e-2.
TEST(CoveredFluid, MovesWithTheTowedBody) {
  check(sphere(6), Motion::towed, 0.04, 0.045);
  check(cube(10), Motion::towed, 0.04, 0.045);
}

// Spinning, measured: against rho_0 I w 2.52e-2 / 2.46e-2, against the field 4.01e-2 / 4.16e-2.
TEST(CoveredFluid, TurnsWithTheSpinningBody) {
  check(sphere(6), Motion::spinning, 0.07, 0.045);
  check(cube(10), Motion::spinning, 0.07, 0.045);
}

// Accelerated from rest, measured: the rate against rho_0 V a 3.09e-2 / 3.03e-2, Q against the
// field 3.57e-2 / 3.87e-2.
TEST(CoveredFluid, AcceleratesWithTheBody) {
  check(sphere(6), Motion::accelerating, 0.07, 0.055);
  check(cube(10), Motion::accelerating, 0.07, 0.055);
}

}  // namespace
}  // namespace lbdem::hlbm
