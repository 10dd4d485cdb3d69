#include "dem_app/external_load.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lbdem {

namespace {

using Mat4 = std::array<std::array<double, 4>, 4>;

// Cyclic Jacobi rotations for a symmetric 4x4 matrix: eigenvalues, eigenvectors as columns of
// v. Plain arrays: Eigen's 4x4 AVX-512 reductions trip GCC 12's -Wmaybe-uninitialized.
std::array<double, 4> jacobi_eigen(Mat4 a, Mat4& v) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v[i][j] = i == j ? 1.0 : 0.0;
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = 0, all = 0;
    for (int p = 0; p < 4; ++p)
      for (int q = 0; q < 4; ++q) {
        all += a[p][q] * a[p][q];
        if (q > p) off += a[p][q] * a[p][q];
      }
    if (off <= 1e-30 * all) break;
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q) {
        if (a[p][q] == 0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t =
            (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        for (int k = 0; k < 4; ++k) {  // a <- a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 4; ++k) {  // a <- J^T a
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 4; ++k) {  // v <- v J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
  }
  return {a[0][0], a[1][1], a[2][2], a[3][3]};
}

}  // namespace

std::vector<double> force_weights(const Clump& clump) {
  // Least-norm solution of A w = b with columns a_i = (1, c_i) and b = (1, 0, 0, 0):
  // w_i = a_i . (A A^T)^+ b. A A^T is 4x4 and singular for planar or collinear clumps, so its
  // pseudo-inverse comes from an eigen-decomposition.
  double scale = 0;  // body size: coordinates are scaled by it, the residual judged against it
  for (size_t k = 0; k < clump.centers.size(); ++k)
    scale = std::max(scale, clump.centers[k].norm() + clump.radii[k]);
  Mat4 m{};
  for (const auto& c : clump.centers) {
    const std::array<double, 4> a{1.0, c[0] / scale, c[1] / scale, c[2] / scale};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) m[i][j] += a[i] * a[j];
  }
  Mat4 v{};
  const auto val = jacobi_eigen(m, v);
  double largest = 0;
  for (double x : val) largest = std::max(largest, std::abs(x));
  // y = V diag(1/lambda) V^T e_0, dropping null directions.
  std::array<double, 4> y{};
  for (int k = 0; k < 4; ++k) {
    if (!(val[k] > 1e-12 * largest)) continue;
    for (int i = 0; i < 4; ++i) y[i] += v[i][k] * v[0][k] / val[k];
  }
  std::vector<double> w;
  std::array<double, 4> sum{};
  for (const auto& c : clump.centers) {
    const std::array<double, 4> a{1.0, c[0] / scale, c[1] / scale, c[2] / scale};
    w.push_back(a[0] * y[0] + a[1] * y[1] + a[2] * y[2] + a[3] * y[3]);
    for (int i = 0; i < 4; ++i) sum[i] += w.back() * a[i];
  }
  // The residual moment arm, relative to the body size.
  const double moment = std::sqrt(sum[1] * sum[1] + sum[2] * sum[2] + sum[3] * sum[3]);
  if (std::abs(sum[0] - 1.0) > 1e-10 || moment > 1e-10)
    throw std::invalid_argument(
        "the clump spheres cannot carry a force through the centre of mass without a torque "
        "(the centre of mass lies outside the span of the sphere centres)");
  return w;
}

void write_applied(double* columns, const AppliedLoad& load) {
  for (int d = 0; d < 3; ++d) {
    columns[kForce + d] = load.force[d];
    columns[kTorque + d] = load.torque[d];
    columns[kKickForce + d] = load.kick_force[d];
    columns[kKickTorque + d] = load.kick_torque[d];
  }
}

void ExternalLoads::apply(int nlocal, double* const* columns, double** fext, double** torque) {
  for (int i = 0; i < nlocal; ++i) {
    const double* c = columns[i];
    for (int d = 0; d < 3; ++d) {
      const double f = c[kForce + d] + (kick_ ? c[kKickForce + d] : 0.0);
      const double t = c[kTorque + d] + (kick_ ? c[kKickTorque + d] : 0.0);
      fext[i][d] = c[kWeight] * f;
      torque[i][d] += c[kTorqueShare] * t;
    }
  }
  kick_ = false;
}

}  // namespace lbdem
