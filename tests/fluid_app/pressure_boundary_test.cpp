// Pressure (anti-bounce-back) faces driving a plane Poiseuille flow between two walls:
// the prescribed densities must be held at the faces and the profile must match
// u(y) = G y (H - y) / (2 rho nu), G = c_s^2 (rho_in - rho_out) / L.
#include <gtest/gtest.h>
#include <mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"

namespace lbdem {
namespace {

TEST(PressureBoundary, DrivesPoiseuilleFlowBetweenWalls) {
  const auto t0 = std::chrono::steady_clock::now();
  const int nx = 40, ny = 11;
  const double tau = 0.8, rho_in = 1.003, rho_out = 0.997;
  FluidParams p = testing_fluid::lattice_params(nx, ny, 1, tau);
  p.faces[0] = {FaceType::pressure, {}, 1000.0 * (rho_in - 1) / 3};
  p.faces[1] = {FaceType::pressure, {}, 1000.0 * (rho_out - 1) / 3};
  p.faces[2].type = p.faces[3].type = FaceType::wall;
  FluidSolver<double> s(p, MPI_COMM_SELF);
  for (int n = 0; n < 8000; ++n) s.step();

  const LocalBox& b = s.box();
  const double nu = (tau - 0.5) / 3;
  auto rho_at = [&](int x) {
    double r = 0;
    for (int y = 1; y <= ny; ++y) r += s.density(b.index(x, y, 1));
    return r / ny;
  };
  // Profile at mid-length against the parabola (walls half-way at y = 0 and H), once with
  // the nominal gradient (ends at the prescribed densities) and once with the gradient the
  // interior actually carries (checks the flow between the walls on its own).
  auto profile_error = [&](double G) {
    double err2 = 0, ref2 = 0;
    for (int y = 1; y <= ny; ++y) {
      const double yy = y - 0.5, exact = G * yy * (ny - yy) / (2 * nu);
      const CellIndex c = b.index(nx / 2, y, 1);
      const double u = s.velocity(c)[0] * s.density(c);  // momentum: rho varies along x
      err2 += (u - exact) * (u - exact);
      ref2 += exact * exact;
    }
    return std::sqrt(err2 / ref2);
  };
  const double nominal = profile_error((rho_in - rho_out) / 3 / nx);
  const double local = profile_error((rho_at(nx / 2 - 5) - rho_at(nx / 2 + 5)) / 3 / 10);
  // Densities extrapolated linearly to the faces (half a cell beyond the end nodes).
  const double face_in = 1.5 * rho_at(1) - 0.5 * rho_at(2);
  const double face_out = 1.5 * rho_at(nx) - 0.5 * rho_at(nx - 1);
  const double dr = rho_in - rho_out;
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "Poiseuille (pressure faces): profile L2 error %.3e vs nominal drop, %.3e vs local "
      "gradient; face density error in %.3e out %.3e (of the drop); run time %.2f s\n",
      nominal, local, (face_in - rho_in) / dr, (face_out - rho_out) / dr, secs);
  EXPECT_LT(local, 0.01);
  EXPECT_LT(nominal, 0.03);
  EXPECT_NEAR(face_in, rho_in, 0.02 * dr);
  EXPECT_NEAR(face_out, rho_out, 0.02 * dr);
  // Mass flux is the same through every cross-section.
  auto flux = [&](int x) {
    double q = 0;
    for (int y = 1; y <= ny; ++y) {
      const CellIndex c = b.index(x, y, 1);
      q += s.velocity(c)[0] * s.density(c);
    }
    return q;
  };
  EXPECT_NEAR(flux(2), flux(nx - 1), 1e-3 * flux(nx / 2));
}

}  // namespace
}  // namespace lbdem
