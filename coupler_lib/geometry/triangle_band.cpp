#include "coupler_lib/geometry/triangle_band.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lbdem {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// An interval of z on the line; empty when lo > hi.
struct Range {
  double lo = -kInf, hi = kInf;
  bool empty() const { return lo > hi; }
  // Keep the z where alpha + beta z >= 0.
  void keep_nonnegative(double alpha, double beta) {
    if (beta > 0)
      lo = std::max(lo, -alpha / beta);
    else if (beta < 0)
      hi = std::min(hi, -alpha / beta);
    else if (alpha < 0)
      lo = kInf;
  }
};

// Ball of radius r about v: (x - vx)^2 + (y - vy)^2 + (z - vz)^2 <= r^2.
Range ball(const Eigen::Vector3d& v, double r, double x, double y) {
  const double d2 = (x - v.x()) * (x - v.x()) + (y - v.y()) * (y - v.y());
  if (d2 > r * r) return {kInf, -kInf};
  const double s = std::sqrt(r * r - d2);
  return {v.z() - s, v.z() + s};
}

// Cylinder of radius r about the segment a-b (without its end caps, which the balls hold):
// with w = q - a, u = b - a and q = (x, y, 0), the point q + z e_z lies at squared distance
// |w + z e_z|^2 - ((w + z e_z).u)^2 / |u|^2 from the edge's line, a quadratic in z, and
// projects on the segment where 0 <= (w + z e_z).u <= |u|^2. A vertical edge adds nothing
// to the balls at its ends within the union's hull, so it is skipped.
Range cylinder(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r, double x, double y) {
  const Eigen::Vector3d u = b - a, w = Eigen::Vector3d(x, y, 0) - a;
  const double L2 = u.squaredNorm(), wu = w.dot(u);
  const double A = 1 - u.z() * u.z() / L2;
  if (!(A > 1e-12)) return {kInf, -kInf};
  const double B = w.z() - wu * u.z() / L2, C = w.squaredNorm() - wu * wu / L2 - r * r;
  const double disc = B * B - A * C;
  if (disc < 0) return {kInf, -kInf};
  const double s = std::sqrt(disc);
  Range range{(-B - s) / A, (-B + s) / A};
  range.keep_nonnegative(wu, u.z());        // (w + z e_z).u >= 0
  range.keep_nonnegative(L2 - wu, -u.z());  // (w + z e_z).u <= |u|^2
  return range;
}

// Prism {s + t n : s in the triangle, |t| <= r}: within r of the triangle's plane and inside
// the three planes through the edges along the normal (inward in-plane normals n x edge for
// counter-clockwise vertices).
Range prism(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double r,
            double x, double y) {
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double norm = n.norm();
  if (!(norm > 0)) return {kInf, -kInf};
  const Eigen::Vector3d nh = n / norm, q(x, y, 0);
  Range range;
  const double h0 = (q - a).dot(nh);
  range.keep_nonnegative(r - h0, -nh.z());  // (p - a).nh <= r
  range.keep_nonnegative(r + h0, nh.z());   // (p - a).nh >= -r
  const Eigen::Vector3d* v[3] = {&a, &b, &c};
  for (int e = 0; e < 3; ++e) {
    const Eigen::Vector3d& p0 = *v[e];
    const Eigen::Vector3d m = n.cross(*v[(e + 1) % 3] - p0);
    range.keep_nonnegative((q - p0).dot(m), m.z());
  }
  return range;
}

}  // namespace

bool near_triangle_interval(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c, double r, double x, double y, double& z0,
                            double& z1) {
  z0 = kInf;
  z1 = -kInf;
  const Range pieces[7] = {ball(a, r, x, y),        ball(b, r, x, y),
                           ball(c, r, x, y),        cylinder(a, b, r, x, y),
                           cylinder(b, c, r, x, y), cylinder(c, a, r, x, y),
                           prism(a, b, c, r, x, y)};
  for (const Range& p : pieces) {
    if (p.empty()) continue;
    z0 = std::min(z0, p.lo);
    z1 = std::max(z1, p.hi);
  }
  if (z0 > z1) return false;
  // The neighbourhood lies within r of the vertices' z range; the clip only removes what
  // round-off in a nearly vertical prism or cylinder could add.
  z0 = std::max(z0, std::min({a.z(), b.z(), c.z()}) - r);
  z1 = std::min(z1, std::max({a.z(), b.z(), c.z()}) + r);
  return z0 <= z1;
}

}  // namespace lbdem
