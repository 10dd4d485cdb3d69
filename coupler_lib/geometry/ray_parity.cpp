#include "coupler_lib/geometry/ray_parity.hpp"

#include <cmath>

namespace lbdem {

namespace {

// Exact sign of a sum of products, for the side test when floating point cannot decide it
// (J. R. Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", 1997): each product is split exactly into two doubles (fma), the terms are
// summed into a non-overlapping expansion (Grow-Expansion, two-sum), whose sign is that of its
// largest component.
void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bv = s - a, av = s - bv;
  e = (a - av) + (b - bv);
}

int exact_sign(const double (&products)[6][2]) {
  double expansion[12];
  int n = 0;
  for (const auto& pr : products) {
    const double hi = pr[0] * pr[1], lo = std::fma(pr[0], pr[1], -hi);
    for (const double term : {lo, hi}) {
      double q = term;
      for (int i = 0; i < n; ++i) two_sum(q, expansion[i], q, expansion[i]);
      expansion[n++] = q;
    }
  }
  for (int i = n - 1; i >= 0; --i)
    if (expansion[i] != 0) return expansion[i] > 0 ? 1 : -1;
  return 0;
}

// Sign of (qx - px)(y - py) - (qy - py)(x - px): the rounded value where it is certain (the
// error bound of orient2d, Shewchuk's ccwerrboundA), else exactly, as
// qx y - qx py - px y - qy x + qy px + py x. Every edge so sees the one true position of the
// point, so the signs around a vertex the line passes within round-off of stay consistent.
int orientation(const Eigen::Vector3d& p, const Eigen::Vector3d& q, double x, double y) {
  const double left = (q.x() - p.x()) * (y - p.y()), right = (q.y() - p.y()) * (x - p.x());
  const double det = left - right;
  constexpr double kBound = (3.0 + 16.0 * 1.1102230246251565e-16) * 1.1102230246251565e-16;
  if (std::abs(det) > kBound * (std::abs(left) + std::abs(right))) return det > 0 ? 1 : -1;
  const double products[6][2] = {{q.x(), y},  {-q.x(), p.y()}, {-p.x(), y},
                                 {-q.y(), x}, {q.y(), p.x()},  {p.y(), x}};
  return exact_sign(products);
}

// Side of the point (x, y) relative to the directed edge u -> v in the xy projection, with
// the edge taken from the lower to the higher vertex index: > 0 left, < 0 right, never 0.
// The tie-break is the sign of cross(v - u, (eps, eps^2)) = -dy*eps + dx*eps^2.
int edge_side(int iu, const Eigen::Vector3d& u, int iv, const Eigen::Vector3d& v, double x,
              double y) {
  const bool flip = iv < iu;
  const Eigen::Vector3d& p = flip ? v : u;
  const Eigen::Vector3d& q = flip ? u : v;
  const double dx = q.x() - p.x(), dy = q.y() - p.y();
  int s = orientation(p, q, x, y);
  if (s == 0) s = dy != 0 ? (dy < 0 ? 1 : -1) : (dx > 0 ? 1 : -1);
  return flip ? -s : s;
}

}  // namespace

bool pierces_column(const std::array<int, 3>& idx, const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b, const Eigen::Vector3d& c, double x, double y,
                    double& z) {
  // Projected orientation; the line is inside iff all three sides agree with it.
  const double area = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  if (area == 0) return false;
  const int want = area > 0 ? 1 : -1;
  if (edge_side(idx[0], a, idx[1], b, x, y) != want) return false;
  if (edge_side(idx[1], b, idx[2], c, x, y) != want) return false;
  if (edge_side(idx[2], c, idx[0], a, x, y) != want) return false;
  // Height of the plane at (x, y) from the barycentric weights of the projection.
  const double wa = ((b.x() - x) * (c.y() - y) - (b.y() - y) * (c.x() - x)) / area;
  const double wb = ((c.x() - x) * (a.y() - y) - (c.y() - y) * (a.x() - x)) / area;
  const double wc = 1.0 - wa - wb;
  z = wa * a.z() + wb * b.z() + wc * c.z();
  return true;
}

}  // namespace lbdem
