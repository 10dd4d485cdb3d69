#include "coupler_lib/geometry/mass_properties.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace lbdem {

MassProperties mass_properties(const Voxels& v) {
  MassProperties m;
  const double h = v.h, dv = h * h * h;
  // Sums relative to the lattice origin first, then shifted to the centroid (parallel
  // axes), in long double: a fine lattice adds ~1e8 terms.
  long double count = 0, s1[3] = {0, 0, 0}, s2[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        if (!v.solid[v.index(i, j, k)]) continue;
        const long double r[3] = {static_cast<long double>(i), static_cast<long double>(j),
                                  static_cast<long double>(k)};
        count += 1;
        for (int a = 0; a < 3; ++a) {
          s1[a] += r[a];
          for (int b = 0; b < 3; ++b) s2[a][b] += r[a] * r[b];
        }
      }
  if (count == 0) return m;
  m.volume = static_cast<double>(count) * dv;
  Eigen::Vector3d mean;
  for (int a = 0; a < 3; ++a) mean[a] = static_cast<double>(s1[a] / count);
  m.centroid = v.origin + h * mean;
  // Second moments about the centroid in lattice units: C_ab = sum r_a r_b - N mean_a mean_b.
  Eigen::Matrix3d c;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      c(a, b) = static_cast<double>(s2[a][b] - count * static_cast<long double>(mean[a]) *
                                                   static_cast<long double>(mean[b]));
  c *= h * h * dv;
  // I = tr(C) 1 - C for the voxel centres, plus each voxel's own inertia (h^2 / 6) dV.
  m.inertia = c.trace() * Eigen::Matrix3d::Identity() - c +
              (m.volume * h * h / 6.0) * Eigen::Matrix3d::Identity();
  principal_axes(m.inertia, m.principal_moments, m.principal_axes);
  return m;
}

void principal_axes(const Eigen::Matrix3d& inertia, Eigen::Vector3d& moments,
                    Eigen::Matrix3d& axes) {
  const Eigen::Matrix3d sym = 0.5 * (inertia + inertia.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(sym);
  moments = solver.eigenvalues();  // ascending
  axes = solver.eigenvectors();
  // A rotation, so it can be used as an orientation: flip the last axis if left-handed.
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
}

double bounding_radius(const Voxels& v, const Eigen::Vector3d& center) {
  double r2 = 0;
  const double half = 0.5 * v.h;
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        if (!v.solid[v.index(i, j, k)]) continue;
        // The farthest corner of a voxel is the one away from the centre on every axis.
        const Eigen::Vector3d d = v.center(i, j, k) - center;
        r2 = std::max(r2, (d.cwiseAbs().array() + half).matrix().squaredNorm());
      }
  return std::sqrt(r2);
}

}  // namespace lbdem
