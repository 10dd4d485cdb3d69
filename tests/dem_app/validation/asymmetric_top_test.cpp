// Torque-free asymmetric top: a cuboid with three different moments spinning about a
// non-principal axis. Kinetic energy and angular momentum are conserved; the body-frame
// angular velocity follows Euler's equations I dw/dt = -w x I w, integrated here
// independently (RK4, step 1e-5 s) from the same inertia tensor the engine was given (the
// integrator's check; that tensor against the cuboid's closed form: mass_properties_test.cpp).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "dem_app/engine/quaternion.hpp"
#include "validation_support.hpp"

namespace lbdem {
namespace {

Eigen::Vector3d euler_rate(const Eigen::Matrix3d& inertia, const Eigen::Matrix3d& inverse,
                           const Eigen::Vector3d& w) {
  return inverse * (-w.cross(inertia * w));
}

TEST(AsymmetricTop, ConservesEnergyAndMomentumAndFollowsEuler) {
  test::WallTimer timer;
  const DemSetup setup = test::load_setup(test::validation_scene("asymmetric_top.yaml"));
  LammpsEngine engine(MPI_COMM_WORLD, setup);
  const Eigen::Matrix3d inertia = engine.body_inertia(0);  // shape frame, kg m^2
  const Eigen::Matrix3d inverse = inertia.inverse();
  const Eigen::Vector3d w0 = to_eigen(setup.bodies[0].angular_velocity);  // q0 = identity
  const double e0 = 0.5 * w0.dot(inertia * w0);
  const Eigen::Vector3d l0 = inertia * w0;

  const double t_end = load_scene(test::validation_scene("asymmetric_top.yaml")).time.end;
  engine.run(std::lround(t_end / engine.dt()));
  const auto s = test::all_states(engine)[0];
  const Eigen::Matrix3d rot =
      Eigen::Quaterniond(s.q[0], s.q[1], s.q[2], s.q[3]).normalized().toRotationMatrix();
  const Eigen::Vector3d w_space(s.w[0], s.w[1], s.w[2]);
  const Eigen::Vector3d w_body = rot.transpose() * w_space;
  const double e = 0.5 * w_body.dot(inertia * w_body);
  const Eigen::Vector3d l = rot * inertia * w_body;

  Eigen::Vector3d w = w0;
  const double h = 1e-5;
  const long n = std::lround(engine.time() / h);
  for (long i = 0; i < n; ++i) {
    const Eigen::Vector3d k1 = euler_rate(inertia, inverse, w);
    const Eigen::Vector3d k2 = euler_rate(inertia, inverse, w + 0.5 * h * k1);
    const Eigen::Vector3d k3 = euler_rate(inertia, inverse, w + 0.5 * h * k2);
    const Eigen::Vector3d k4 = euler_rate(inertia, inverse, w + h * k3);
    w += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const double energy_error = std::abs(e - e0) / e0;
  const double momentum_error = (l - l0).norm() / l0.norm();
  const double euler_error = (w_body - w).norm() / w.norm();
  const double seconds = timer.seconds();
  test::report("asymmetric top, 1 s", "kinetic energy relative", energy_error, 1e-5, seconds);
  test::report("asymmetric top, 1 s", "angular momentum relative", momentum_error, 1e-5, seconds);
  test::report("asymmetric top, 1 s", "body-frame omega vs Euler (RK4) relative", euler_error, 1e-3,
               seconds);
  // It really tumbles: the body-frame spin axis moves far from where it started.
  EXPECT_GT((w - w0).norm() / w0.norm(), 0.1);
  EXPECT_LT(energy_error, 1e-5);
  EXPECT_LT(momentum_error, 1e-5);
  EXPECT_LT(euler_error, 1e-3);
}

}  // namespace
}  // namespace lbdem
