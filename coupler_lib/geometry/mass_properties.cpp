#include "coupler_lib/geometry/mass_properties.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lbdem {

namespace {

// Volume, centroid (input frame) and second moments C = int (x - c)(x - c)^T dV about the
// centroid, turned into I = tr(C) 1 - C and its principal axes.
MassProperties from_moments(double volume, const Eigen::Vector3d& centroid,
                            const Eigen::Matrix3d& second) {
  MassProperties m;
  m.volume = volume;
  m.centroid = centroid;
  m.inertia = second.trace() * Eigen::Matrix3d::Identity() - second;
  principal_axes(m.inertia, m.principal_moments, m.principal_axes);
  return m;
}

// A closed mesh with outward normals: each triangle (a, b, c) and the reference point o span
// a signed tetrahedron of determinant D = a'.(b' x c') (primes: relative to o), which adds
// D/6 to the volume, D/24 (a' + b' + c') to the first moment and
// D/120 (s s^T + a' a'^T + b' b'^T + c' c'^T), s = a' + b' + c', to the second moment.
// o is the middle of the bounding box, which keeps the sums free of cancellation for a mesh
// far from its file's origin.
MassProperties mesh_mass_properties(const TriangleMesh& mesh) {
  Eigen::Vector3d lo, hi;
  bounding_box(mesh, lo, hi);
  const Eigen::Vector3d o = 0.5 * (lo + hi);
  double six_v = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] - o, b = mesh.vertices[t[1]] - o,
                          c = mesh.vertices[t[2]] - o;
    const double d = a.dot(b.cross(c));
    const Eigen::Vector3d s = a + b + c;
    six_v += d;
    first += d * s;
    second += d * (s * s.transpose() + a * a.transpose() + b * b.transpose() + c * c.transpose());
  }
  const double volume = six_v / 6.0;
  const Eigen::Vector3d centroid = first / 24.0 / volume;
  const Eigen::Matrix3d about_centroid = second / 120.0 - volume * centroid * centroid.transpose();
  return from_moments(volume, o + centroid, about_centroid);
}

}  // namespace

MassProperties mass_properties(const SolidGeometry& solid) {
  const Eigen::Vector3d& p = solid.parameters();
  const double volume = solid.exact_volume();
  // Analytic kinds are centred at the origin with their axes along x, y, z; the second
  // moments are diagonal: V r^2 / 5 (sphere), V e_i^2 / 12 (cuboid edges e),
  // V e_i^2 / 5 (ellipsoid semi-axes e).
  switch (solid.kind()) {
    case SolidGeometry::Kind::sphere:
      return from_moments(volume, Eigen::Vector3d::Zero(),
                          Eigen::Matrix3d::Identity() * (volume * p.x() * p.x() / 5.0));
    case SolidGeometry::Kind::cuboid:
      return from_moments(volume, Eigen::Vector3d::Zero(),
                          (volume / 12.0 * p.cwiseProduct(p)).asDiagonal().toDenseMatrix());
    case SolidGeometry::Kind::ellipsoid:
      return from_moments(volume, Eigen::Vector3d::Zero(),
                          (volume / 5.0 * p.cwiseProduct(p)).asDiagonal().toDenseMatrix());
    case SolidGeometry::Kind::mesh:
      return mesh_mass_properties(solid.triangles());
  }
  return {};
}

MassProperties mass_properties(const Voxels& v) {
  const double h = v.h, dv = h * h * h;
  // Sums relative to the lattice origin first, then shifted to the centroid (parallel
  // axes), in long double: a fine lattice adds ~1e8 terms.
  long double total = 0, s1[3] = {0, 0, 0}, s2[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int k = 0; k < v.n[2]; ++k)
    for (int j = 0; j < v.n[1]; ++j)
      for (int i = 0; i < v.n[0]; ++i) {
        const long double w = v.fill[v.index(i, j, k)];
        if (w == 0) continue;
        const long double r[3] = {static_cast<long double>(i), static_cast<long double>(j),
                                  static_cast<long double>(k)};
        total += w;
        for (int a = 0; a < 3; ++a) {
          s1[a] += w * r[a];
          for (int b = 0; b < 3; ++b) s2[a][b] += w * r[a] * r[b];
        }
      }
  if (total == 0) return {};
  Eigen::Vector3d mean;
  for (int a = 0; a < 3; ++a) mean[a] = static_cast<double>(s1[a] / total);
  // Second moments about the centroid in lattice units: C_ab = sum w r_a r_b - W mean_a mean_b,
  // plus each voxel's own second moment (h^2 / 12 per axis) weighted by its fill.
  Eigen::Matrix3d c;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      c(a, b) = static_cast<double>(s2[a][b] - total * static_cast<long double>(mean[a]) *
                                                   static_cast<long double>(mean[b]));
  const double volume = static_cast<double>(total) * dv;
  c = c * (h * h * dv) + Eigen::Matrix3d::Identity() * (volume * h * h / 12.0);
  return from_moments(volume, v.origin + h * mean, c);
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
        if (v.fill[v.index(i, j, k)] == 0) continue;
        // The farthest corner of a voxel is the one away from the centre on every axis.
        const Eigen::Vector3d d = v.center(i, j, k) - center;
        r2 = std::max(r2, (d.cwiseAbs().array() + half).matrix().squaredNorm());
      }
  return std::sqrt(r2);
}

}  // namespace lbdem
