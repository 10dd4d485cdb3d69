#include "coupler_lib/geometry/solid_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "coupler_lib/geometry/ray_parity.hpp"

namespace lbdem {

namespace {

double segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

// Distance from p to a triangle: to its plane when p projects inside, else to the nearest
// of its edges.
double triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  const Eigen::Vector3d q = p - n * ((p - a).dot(n) / n2);
  const bool in = (b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
                  (a - c).cross(q - c).dot(n) >= 0;
  if (in) return std::abs((p - a).dot(n)) / std::sqrt(n2);
  return std::min(
      {segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
}

// Distance from y to the ellipsoid sum (x_i / e_i)^2 = 1. The nearest point is
// x_i = e_i^2 y_i / (t + e_i^2) with t the root of G(t) = sum (e_i y_i / (t + e_i^2))^2 - 1
// on t > -e_min^2 (Lagrange condition; G decreases monotonically there). When y lies in the
// plane(s) of the smallest axis and G(-e_min^2) <= 0, the nearest point leaves that plane
// and its out-of-plane component closes the constraint (D. Eberly, "Distance from a point
// to an ellipse, an ellipsoid, or a hyperellipsoid", 2013).
double ellipsoid_distance(const Eigen::Vector3d& e, Eigen::Vector3d y) {
  y = y.cwiseAbs();
  // Components within round-off of a symmetry plane are put on it (the distance is
  // 1-Lipschitz, so this moves it by at most 1e-9 e_max): otherwise the root t sits within
  // an ulp of -e_min^2 and x_i = e_i^2 y_i / (t + e_i^2) divides by zero.
  for (int i = 0; i < 3; ++i)
    if (y[i] <= 1e-9 * e.maxCoeff()) y[i] = 0;
  const double emin = e.minCoeff();
  auto G = [&](double t) {
    double g = -1;
    for (int i = 0; i < 3; ++i) {
      if (y[i] == 0) continue;
      const double r = e[i] * y[i] / (t + e[i] * e[i]);
      g += r * r;
    }
    return g;
  };
  bool min_axis_free = true;  // every component along a smallest axis is zero
  for (int i = 0; i < 3; ++i)
    if (e[i] == emin && y[i] != 0) min_axis_free = false;
  const double t_lo = -emin * emin;
  if (min_axis_free) {
    const double g = G(t_lo);
    if (g <= 0) {
      double d2 = 0;
      for (int i = 0; i < 3; ++i) {
        if (e[i] == emin) continue;
        const double xi = e[i] * e[i] * y[i] / (e[i] * e[i] - emin * emin);
        d2 += (xi - y[i]) * (xi - y[i]);
      }
      return std::sqrt(d2 + emin * emin * (-g));
    }
  }
  if (y.norm() == 0) return emin;
  double lo = t_lo, hi = y.norm() * e.maxCoeff();
  for (int it = 0; it < 200 && hi - lo > 0; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (G(mid) > 0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  double d2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double xi = e[i] * e[i] * y[i] / (t + e[i] * e[i]);
    d2 += (xi - y[i]) * (xi - y[i]);
  }
  return std::sqrt(d2);
}

}  // namespace

SolidGeometry SolidGeometry::sphere(double radius) {
  SolidGeometry g;
  g.kind_ = Kind::sphere;
  g.p_ = Eigen::Vector3d::Constant(radius);
  g.hi_ = g.p_;
  g.lo_ = -g.p_;
  return g;
}

SolidGeometry SolidGeometry::cuboid(const Eigen::Vector3d& edges) {
  SolidGeometry g;
  g.kind_ = Kind::cuboid;
  g.p_ = edges;
  g.hi_ = edges / 2;
  g.lo_ = -g.hi_;
  return g;
}

SolidGeometry SolidGeometry::ellipsoid(const Eigen::Vector3d& semi_axes) {
  SolidGeometry g;
  g.kind_ = Kind::ellipsoid;
  g.p_ = semi_axes;
  g.hi_ = semi_axes;
  g.lo_ = -semi_axes;
  return g;
}

SolidGeometry SolidGeometry::mesh(TriangleMesh m) {
  SolidGeometry g;
  g.kind_ = Kind::mesh;
  bounding_box(m, g.lo_, g.hi_);
  g.p_ = g.hi_ - g.lo_;
  g.mesh_ = std::make_shared<const TriangleMesh>(std::move(m));
  return g;
}

bool SolidGeometry::inside(const Eigen::Vector3d& x) const {
  switch (kind_) {
    case Kind::sphere:
      return x.squaredNorm() < p_.x() * p_.x();
    case Kind::cuboid:
      return (x.cwiseAbs().array() < (p_ / 2).array()).all();
    case Kind::ellipsoid:
      return x.cwiseQuotient(p_).squaredNorm() < 1.0;
    case Kind::mesh: {
      // Parity of the crossings of the upward ray from x.
      int crossings = 0;
      const auto& m = *mesh_;
      for (const auto& t : m.triangles) {
        double z;
        if (pierces_column(t, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]], x.x(), x.y(),
                           z) &&
            z > x.z())
          ++crossings;
      }
      return crossings % 2 == 1;
    }
  }
  return false;
}

double SolidGeometry::distance_to_surface(const Eigen::Vector3d& x) const {
  switch (kind_) {
    case Kind::sphere:
      return std::abs(x.norm() - p_.x());
    case Kind::cuboid: {
      const Eigen::Vector3d q = x.cwiseAbs() - p_ / 2;
      if ((q.array() > 0).any()) return q.cwiseMax(0.0).norm();
      return -q.maxCoeff();
    }
    case Kind::ellipsoid:
      return ellipsoid_distance(p_, x);
    case Kind::mesh: {
      double d = std::numeric_limits<double>::infinity();
      const auto& m = *mesh_;
      for (const auto& t : m.triangles)
        d = std::min(d, triangle_distance(x, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]));
      return d;
    }
  }
  return 0;
}

std::array<double, 2> SolidGeometry::distance_bounds(const Eigen::Vector3d& x) const {
  if (kind_ != Kind::ellipsoid) {
    const double d = distance_to_surface(x);
    return {d, d};
  }
  const double s = x.cwiseQuotient(p_).norm();
  if (!(s > 0)) {
    const double d = distance_to_surface(x);
    return {d, d};
  }
  return {std::abs(1 - s) * p_.minCoeff(), x.norm() * std::abs(1 / s - 1)};
}

double SolidGeometry::exact_volume() const {
  switch (kind_) {
    case Kind::sphere:
      return 4.0 / 3.0 * std::numbers::pi * std::pow(p_.x(), 3);
    case Kind::cuboid:
      return p_.prod();
    case Kind::ellipsoid:
      return 4.0 / 3.0 * std::numbers::pi * p_.prod();
    case Kind::mesh:
      return signed_volume(*mesh_);
  }
  return 0;
}

std::string SolidGeometry::describe() const {
  std::ostringstream s;
  s.precision(8);
  switch (kind_) {
    case Kind::sphere:
      s << "sphere radius " << p_.x();
      break;
    case Kind::cuboid:
      s << "cuboid edges " << p_.x() << " " << p_.y() << " " << p_.z();
      break;
    case Kind::ellipsoid:
      s << "ellipsoid semi-axes " << p_.x() << " " << p_.y() << " " << p_.z();
      break;
    case Kind::mesh:
      s << "mesh of " << mesh_->triangles.size() << " triangles, bounding box " << p_.x() << " "
        << p_.y() << " " << p_.z();
      break;
  }
  return s.str();
}

}  // namespace lbdem
