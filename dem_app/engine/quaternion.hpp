#pragma once
// Conversions between the packets' plain arrays (w, x, y, z) and Eigen.
#include <Eigen/Geometry>

#include <array>

namespace lbdem {

inline Eigen::Quaterniond to_eigen(const std::array<double, 4>& q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}
inline std::array<double, 4> to_array(const Eigen::Quaterniond& q) {
  return {q.w(), q.x(), q.y(), q.z()};
}
inline Eigen::Vector3d to_eigen(const std::array<double, 3>& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace lbdem
