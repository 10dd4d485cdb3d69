#include <gtest/gtest.h>
#include <mpi.h>

#include "fluid_app/forcing/mean_flow_control.hpp"
#include "fluid_app/lattice/d3q19.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"

namespace lbdem {
namespace {

std::array<double, 3> momentum(const FluidSolver<double>& s) {
  std::array<double, 3> m{};
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x)
        for (int i = 0; i < d3q19::Q; ++i)
          for (int k = 0; k < 3; ++k) m[k] += d3q19::c[i][k] * s.population(i, b.index(x, y, z));
  return m;
}

// Exact-difference forcing: every step adds exactly F (times dt = 1) per cell.
TEST(Forcing, UniformForceAddsExactMomentumPerStep) {
  FluidSolver<double> s(testing_fluid::lattice_params(6, 5, 4, 0.7), MPI_COMM_SELF);
  const std::array<double, 3> F = {2e-5, -1e-5, 3e-6};
  s.set_uniform_force(F);
  const double cells = 6 * 5 * 4;
  for (int n = 1; n <= 7; ++n) {
    s.step();
    const auto m = momentum(s);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(m[k], n * cells * F[k], 1e-15 * cells * n) << k;
  }
  // Physical velocity of the uniform state: u* = v + F / (2 rho) = (n + 1/2) F at rho = 1.
  const auto u = s.velocity(s.box().index(2, 2, 2));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(u[k], 7.5 * F[k], 1e-15) << k;
}

// Inside a body (d = 0) the shift sets the velocity to the body's: u+ = u_p.
TEST(Forcing, SolidCellsTakeTheBodyVelocity) {
  FluidSolver<double> s(testing_fluid::lattice_params(6, 6, 6, 0.8), MPI_COMM_SELF);
  PorousField<double>& pf = s.porous();
  std::fill(pf.d.begin(), pf.d.end(), 0.0f);
  std::fill(pf.body.begin(), pf.body.end(), 0);
  pf.bodies = {{{3.0, 3.0, 3.0}, {0.01, -0.02, 0.005}, {0, 0, 0}}};
  pf.active = true;
  s.step();
  s.step();
  const LocalBox& b = s.box();
  for (CellIndex c : {b.index(1, 1, 1), b.index(3, 4, 5), b.index(6, 6, 6)}) {
    const auto u = s.velocity(c);
    EXPECT_NEAR(u[0], 0.01, 1e-15);
    EXPECT_NEAR(u[1], -0.02, 1e-15);
    EXPECT_NEAR(u[2], 0.005, 1e-15);
  }
}

// The controller holds the mean velocity against a constant body force.
TEST(Forcing, MeanVelocityControllerCancelsABodyForce) {
  FluidParams p = testing_fluid::lattice_params(8, 8, 8, 0.8);
  p.body_force = {3e-5, 0, -2e-5};  // lattice units here (acceleration unit = 1)
  p.control.enabled = true;
  p.control.target = {0.0, 0.001, 0.0};
  FluidSolver<double> s(p, MPI_COMM_SELF);
  MeanFlowControl<double> control(s, p);
  for (int n = 0; n < 300; ++n) {
    s.step();
    control.after_step();
  }
  const MeanFlow m = s.mean_flow();
  // The mean is measured in fixed point with 2^-30 (1e-9) lattice units per cell.
  EXPECT_NEAR(m.velocity[0], 0.0, 2e-9);
  EXPECT_NEAR(m.velocity[1], 0.001, 2e-9);
  EXPECT_NEAR(m.velocity[2], 0.0, 2e-9);
  // In steady state the controller's force cancels the body force.
  EXPECT_NEAR(s.uniform_force()[0], 0.0, 2e-9);
  EXPECT_NEAR(s.uniform_force()[2], 0.0, 2e-9);
  EXPECT_NEAR(m.mass, 512.0, 1e-6);
}

}  // namespace
}  // namespace lbdem
