// A given external force and torque on bodies with non-diagonal space-frame inertia:
// a = F / m and dw/dt = I^-1 (T - w x I w), with I = R I_body R^T. Each rank sets the loads
// of the bodies it owns (as the coupler will) and checks those bodies.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

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
  test::report("force and torque, 4 bodies", "a vs F/m relative", lin, seconds);
  test::report("force and torque, 4 bodies",
               "dw/dt vs I^-1 (T - w x I w) relative (central difference over 40 steps)", ang,
               seconds);
  EXPECT_LT(lin, 1e-9);
  EXPECT_LT(ang, 1e-4);
}

}  // namespace
}  // namespace lbdem
