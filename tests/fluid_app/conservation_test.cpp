#include <gtest/gtest.h>
#include <mpi.h>

#include "fluid_app/lattice/d3q19.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"

namespace lbdem {
namespace {

using testing_fluid::wave;

struct Totals {
  double mass = 0;
  std::array<double, 3> momentum{};  // bare momentum sum(c_i f_i)
};

template <class T>
Totals totals(const FluidSolver<T>& s) {
  Totals t;
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x)
        for (int i = 0; i < d3q19::Q; ++i) {
          const double f = s.population(i, b.index(x, y, z));
          t.mass += f;
          for (int k = 0; k < 3; ++k) t.momentum[k] += d3q19::c[i][k] * f;
        }
  return t;
}

template <class T>
void perturb(FluidSolver<T>& s) {
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x)
        s.set_equilibrium(
            b.index(x, y, z), T(1 + 0.02 * wave(x, y, z, 0)),
            {T(0.03 * wave(x, y, z, 1)), T(0.03 * wave(x, y, z, 2)), T(0.03 * wave(x, y, z, 3))});
}

TEST(Conservation, PeriodicBoxKeepsMassAndMomentumDouble) {
  FluidSolver<double> s(testing_fluid::lattice_params(9, 8, 7, 0.62), MPI_COMM_SELF);
  perturb(s);
  const Totals t0 = totals(s);
  for (int n = 0; n < 11; ++n) s.step();  // odd count: ends in the swapped AA layout
  const Totals t1 = totals(s);
  EXPECT_NEAR(t1.mass, t0.mass, 1e-11);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(t1.momentum[k], t0.momentum[k], 1e-12) << k;
}

TEST(Conservation, PeriodicBoxKeepsMassAndMomentumFloat) {
  FluidSolver<float> s(testing_fluid::lattice_params(9, 8, 7, 0.62), MPI_COMM_SELF);
  perturb(s);
  const Totals t0 = totals(s);
  for (int n = 0; n < 10; ++n) s.step();
  const Totals t1 = totals(s);
  // Float rounding: 504 cells x 19 values near 0.05 each step.
  EXPECT_NEAR(t1.mass, t0.mass, 2e-3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(t1.momentum[k], t0.momentum[k], 2e-4) << k;
}

TEST(Conservation, ClosedBoxAtRestStaysAtRestWithBounceBack) {
  FluidParams p = testing_fluid::lattice_params(6, 5, 4, 0.8);
  for (auto& f : p.faces) f.type = FaceType::wall;
  FluidSolver<double> s(p, MPI_COMM_SELF);
  for (int n = 0; n < 25; ++n) s.step();
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const auto u = s.velocity(b.index(x, y, z));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(u[k], 0.0, 1e-15) << x << y << z;  // round-off
        EXPECT_NEAR(s.density(b.index(x, y, z)), 1.0, 1e-15);
      }
}

TEST(Conservation, ClosedBoxKeepsMassOfAPerturbedState) {
  FluidParams p = testing_fluid::lattice_params(6, 5, 4, 0.8);
  for (auto& f : p.faces) f.type = FaceType::wall;
  FluidSolver<double> s(p, MPI_COMM_SELF);
  perturb(s);
  const double m0 = totals(s).mass;
  for (int n = 0; n < 25; ++n) s.step();
  EXPECT_NEAR(totals(s).mass, m0, 1e-12);
}

}  // namespace
}  // namespace lbdem
