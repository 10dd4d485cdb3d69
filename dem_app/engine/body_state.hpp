#pragma once
// Per-body state as read from LAMMPS (compute rigid/local) and converted to the shape's own
// frame. LAMMPS's quaternion maps the principal axes it derived (in an order and sign of its
// choosing) to space; the user's quaternion maps the shape frame to space. Both describe the
// same rotation since t = 0, so q_user(t) = q(t) q(0)^-1 q_user(0); the constant factor
// q(0)^-1 q_user(0) is kept per body.
#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"

namespace lbdem {

// One owned body, everything the engine reads from a compute rigid/local row.
struct BodyRecord {
  std::int64_t id = 0;
  Eigen::Vector3d x, x_unwrapped, v, omega, angmom, force, torque;
  Eigen::Quaterniond q_lammps;  // principal frame -> space
};

// Columns requested from compute rigid/local, in this order.
inline constexpr const char* kRigidLocalColumns =
    "mol x y z xu yu zu vx vy vz omegax omegay omegaz angmomx angmomy angmomz fx fy fz tqx tqy "
    "tqz quatw quati quatj quatk";
inline constexpr int kRigidLocalCount = 26;

BodyRecord record_from_row(const double* row);

// Orientation in the shape frame from LAMMPS's and the stored offset q(0)^-1 q_user(0).
inline Eigen::Quaterniond user_orientation(const Eigen::Quaterniond& q_lammps,
                                           const Eigen::Quaterniond& offset) {
  Eigen::Quaterniond q = q_lammps * offset;
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1;  // one sign for a rotation, for reproducible output
  return q;
}

}  // namespace lbdem
