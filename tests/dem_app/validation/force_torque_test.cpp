// A given external force and torque on bodies with non-diagonal space-frame inertia:
// a = F / m and dw/dt = I^-1 (T - w x I w), with I = R I_body R^T. Each rank sets the loads
// of the bodies it owns (as the coupler will) and checks those bodies. The integrator's check,
// with the engine's mass and inertia; those against the closed form: mass_properties_test.cpp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "validation_support.hpp"

namespace lbdem {
namespace {

Eigen::Vector3d force_of(std::int64_t id) {
  return Eigen::Vector3d(1.0 + id, -0.5 * id, 0.3) * 1e-3;  // N
}
Eigen::Vector3d torque_of(std::int64_t id) {
  return Eigen::Vector3d(0.4, 1.0 - 0.3 * id, -0.7 + 0.2 * id) * 1e-6;  // N m
}

TEST(ForceTorque, AccelerationsMatchNewtonAndEuler) {
  test::WallTimer timer;
  LammpsEngine engine(MPI_COMM_WORLD,
                      test::load_setup(test::validation_scene("force_torque.yaml"), true));
  for (const auto& s : engine.owned_states(0))
    engine.set_load(s.id, force_of(s.id), torque_of(s.id));
  // The first step after set-up uses the set-up's forces (velocity-Verlet half-kick), so
  // the accelerations are measured from step 1 on.
  engine.run(1);
  const long k = 20;
  const double dt = engine.dt();
  const auto a = test::all_states(engine);
  engine.run(k);
  const auto b = test::all_states(engine);
  engine.run(k);
  const auto c = test::all_states(engine);

  double lin = 0, ang = 0;
  for (size_t i = 0; i < b.size(); ++i) {
    const auto id = b[i].id;
    const double m = engine.body_mass(id);
    const Eigen::Vector3d va(a[i].v[0], a[i].v[1], a[i].v[2]);
    const Eigen::Vector3d vc(c[i].v[0], c[i].v[1], c[i].v[2]);
    const Eigen::Vector3d acc = (vc - va) / (2 * k * dt);
    lin = std::max(lin, (acc - force_of(id) / m).norm() / (force_of(id) / m).norm());

    const Eigen::Matrix3d rot =
        Eigen::Quaterniond(b[i].q[0], b[i].q[1], b[i].q[2], b[i].q[3]).toRotationMatrix();
    const Eigen::Matrix3d inertia = rot * engine.body_inertia(id) * rot.transpose();
    const Eigen::Vector3d w(b[i].w[0], b[i].w[1], b[i].w[2]);
    const Eigen::Vector3d expected = inertia.inverse() * (torque_of(id) - w.cross(inertia * w));
    const Eigen::Vector3d wa(a[i].w[0], a[i].w[1], a[i].w[2]);
    const Eigen::Vector3d wc(c[i].w[0], c[i].w[1], c[i].w[2]);
    const Eigen::Vector3d measured = (wc - wa) / (2 * k * dt);
    ang = std::max(ang, (measured - expected).norm() / expected.norm());
    // The space-frame inertia really is non-diagonal.
    EXPECT_GT(std::abs(inertia(0, 1)) + std::abs(inertia(0, 2)) + std::abs(inertia(1, 2)),
              1e-3 * inertia.trace())
        << "body " << id;
  }
  const double seconds = timer.seconds();
  test::report("force and torque, 4 bodies", "a vs F/m relative", lin, 1e-9, seconds);
  test::report("force and torque, 4 bodies",
               "dw/dt vs I^-1 (T - w x I w) relative (central difference over 40 steps)", ang, 1e-4,
               seconds);
  EXPECT_LT(lin, 1e-9);
  EXPECT_LT(ang, 1e-4);
}

// The coupled loop changes the load before every run of n_DEM substeps (`run N pre no`): each
// run must give every body exactly dt N F of the load set for it (docs/method-loads.md, the
// DEM half), also when the load changes from run to run, so that the momentum the fluid gave
// is the momentum the body gets.
TEST(ForceTorque, EachRunDeliversExactlyItsLoadsImpulse) {
  test::WallTimer timer;
  LammpsEngine engine(MPI_COMM_WORLD,
                      test::load_setup(test::validation_scene("force_torque.yaml"), true));
  const auto start = test::all_states(engine);
  const double dt = engine.dt();
  const long substeps[] = {7, 3, 5, 2, 6};
  std::vector<Eigen::Vector3d> impulse(start.size(), Eigen::Vector3d::Zero());
  for (int run = 0; run < 5; ++run) {
    // A different load every run: scaled, and turned a little.
    const double scale = 1.0 + 0.6 * run - 0.15 * run * run;
    for (const auto& st : engine.owned_states(run)) {
      const Eigen::Vector3d f =
          scale * force_of(st.id) + Eigen::Vector3d(0, 2e-4 * run, -1e-4 * run);
      engine.set_load(st.id, f, Eigen::Vector3d::Zero());
    }
    for (const auto& st : start) {
      const Eigen::Vector3d f =
          scale * force_of(st.id) + Eigen::Vector3d(0, 2e-4 * run, -1e-4 * run);
      impulse[static_cast<size_t>(st.id)] += dt * double(substeps[run]) * f;
    }
    engine.run(substeps[run]);
  }
  const auto end = test::all_states(engine);
  // Exact up to round-off: each of the N substeps rounds the velocity once, by up to half an
  // ulp of |v|, so |m dv - J| may reach N eps |v| m (body 0 moves at 0.1 m/s and gains only
  // ~4e-5 m/s here: about 3e-12 of J). The check is against that bound per body.
  const long steps = 7 + 3 + 5 + 2 + 6;
  double worst = 0, worst_bound = 0;
  for (size_t i = 0; i < end.size(); ++i) {
    const auto id = end[i].id;
    const double m = engine.body_mass(id);
    const Eigen::Vector3d v0(start[i].v[0], start[i].v[1], start[i].v[2]);
    const Eigen::Vector3d v1(end[i].v[0], end[i].v[1], end[i].v[2]);
    const Eigen::Vector3d dp = m * (v1 - v0);
    const Eigen::Vector3d& j = impulse[static_cast<size_t>(id)];
    const double round_off =
        double(steps) * std::numeric_limits<double>::epsilon() * m * std::max(v0.norm(), v1.norm());
    const double error = (dp - j).norm() / j.norm(),
                 bound = (round_off + 1e-13 * j.norm()) / j.norm();
    if (error / bound > worst / std::max(worst_bound, 1e-300)) {
      worst = error;
      worst_bound = bound;
    }
  }
  test::report("impulse of changing loads, 4 bodies, 5 runs", "m dv vs sum dt N F relative", worst,
               worst_bound, timer.seconds());
  EXPECT_LT(worst, worst_bound);
}

}  // namespace
}  // namespace lbdem
