// The AA-pattern solver against the plain two-array reference, step by step: this checks the
// in-place streaming of both parities, the parity-free accessor, the boundary rules of every
// face type (edges included) and the forcing, all at once.
#include <gtest/gtest.h>
#include <mpi.h>

#include "fluid_app/solver/fluid_solver.hpp"
#include "tests/fluid_app/fluid_test_setup.hpp"
#include "tests/fluid_app/reference_lattice.hpp"

namespace lbdem {
namespace {

using testing_fluid::ReferenceLattice;
using testing_fluid::wave;

void init_both(FluidSolver<double>& s, ReferenceLattice& ref) {
  const LocalBox& b = s.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const int g[3] = {x - 1, y - 1, z - 1};
        const double rho = 1.0 + 0.01 * wave(g[0], g[1], g[2], 0);
        const std::array<double, 3> u = {0.02 * wave(g[0], g[1], g[2], 1),
                                         0.02 * wave(g[0], g[1], g[2], 2),
                                         0.02 * wave(g[0], g[1], g[2], 3)};
        s.set_equilibrium(b.index(x, y, z), rho, u);
        for (int i = 0; i < d3q19::Q; ++i)
          ref.f[ref.id(g[0], g[1], g[2]) * 19 + i] = d3q19::equilibrium(i, rho, u[0], u[1], u[2]);
      }
}

double max_difference(const FluidSolver<double>& s, const ReferenceLattice& ref) {
  const LocalBox& b = s.box();
  double m = 0;
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x)
        for (int i = 0; i < d3q19::Q; ++i)
          m = std::max(m, std::abs(s.population(i, b.index(x, y, z)) -
                                   ref.f[ref.id(x - 1, y - 1, z - 1) * 19 + i]));
  return m;
}

TEST(AaPattern, MatchesReferenceWithAllFaceTypesAndForce) {
  FluidParams p = testing_fluid::lattice_params(7, 6, 5, 0.7);
  p.faces[0].type = p.faces[1].type = FaceType::periodic;
  p.faces[2].type = FaceType::wall;
  p.faces[3].type = FaceType::moving_wall;
  p.faces[3].velocity = {0.05, 0, 0.02};
  p.faces[4].type = FaceType::pressure;
  p.faces[4].pressure = 1000.0 * 0.004;  // rho_w = 1.012
  p.faces[5].type = FaceType::pressure;
  p.faces[5].pressure = -1000.0 * 0.002;  // rho_w = 0.994
  FluidSolver<double> s(p, MPI_COMM_SELF);
  s.set_uniform_force({1e-4, -2e-4, 5e-5});

  ReferenceLattice ref({7, 6, 5});
  ref.type = {p.faces[0].type, p.faces[1].type, p.faces[2].type,
              p.faces[3].type, p.faces[4].type, p.faces[5].type};
  ref.wall_velocity[3] = {0.05, 0, 0.02};
  ref.wall_density[4] = 1.012;
  ref.wall_density[5] = 0.994;
  ref.omega = 1 / 0.7;
  ref.force = {1e-4, -2e-4, 5e-5};
  init_both(s, ref);
  for (int n = 1; n <= 6; ++n) {
    s.step();
    ref.step();
    EXPECT_LT(max_difference(s, ref), 1e-14) << "after step " << n;
  }
  // Ghost cells along the periodic x axis: outgoing populations equal the wrapped cell's.
  const LocalBox& b = s.box();
  for (int i = 0; i < d3q19::Q; ++i) {
    if (d3q19::c[i][0] != 1 || d3q19::c[i][1] != 0) continue;
    const CellIndex ghost = b.index(b.n[0] + 1, 3, 3 + d3q19::c[i][2]);
    EXPECT_NEAR(s.population(i, ghost), ref.f[ref.id(0, 2, 2 + d3q19::c[i][2]) * 19 + i], 1e-14);
  }
}

TEST(AaPattern, MatchesReferenceWithPorousBodiesAcrossPeriodicFaces) {
  FluidParams p = testing_fluid::lattice_params(8, 6, 6, 0.9);
  FluidSolver<double> s(p, MPI_COMM_SELF);
  ReferenceLattice ref({8, 6, 6});
  ref.omega = 1 / 0.9;
  init_both(s, ref);
  PorousField<double>& pf = s.porous();
  const LocalBox& b = s.box();
  ref.d.assign(std::size_t(ref.cells()), 1.0f);
  ref.body.assign(std::size_t(ref.cells()), -1);
  // Body 0 sits across the x = 0 face (centre at x = 0.5), rotating; body 1 translates;
  // a static porous layer (body -1) at z = 5.
  ref.bodies = {{{0.5, 3.0, 3.0}, {0.01, 0.0, -0.02}, {0.0, 0.0, 0.03}},
                {{5.0, 2.0, 2.0}, {0.0, 0.03, 0.0}, {0.01, 0.0, 0.0}}};
  for (const auto& body : ref.bodies) pf.bodies.push_back(body);
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 8; ++x) {
        float d = 1.0f;
        int body = -1;
        if (x <= 1 || x >= 7) {
          d = float(0.2 + 0.1 * ((x + y + z) % 5));
          body = 0;
        } else if (x >= 4 && x <= 5 && y <= 3) {
          d = 0.0f;
          body = 1;
        } else if (z == 5) {
          d = 0.5f;
        }
        ref.d[ref.id(x, y, z)] = d;
        ref.body[ref.id(x, y, z)] = body;
        pf.d[b.index(x + 1, y + 1, z + 1)] = d;
        pf.body[b.index(x + 1, y + 1, z + 1)] = body;
      }
  pf.active = true;
  for (int n = 1; n <= 5; ++n) {
    s.step();
    ref.step();
    EXPECT_LT(max_difference(s, ref), 1e-14) << "after step " << n;
  }
}

}  // namespace
}  // namespace lbdem
