#include "coupler_lib/geometry/ray_parity.hpp"

namespace lbdem {

namespace {

// Side of the point (x, y) relative to the directed edge u -> v in the xy projection, with
// the edge taken from the lower to the higher vertex index: > 0 left, < 0 right, never 0.
// The tie-break is the sign of cross(v - u, (eps, eps^2)) = -dy*eps + dx*eps^2.
int edge_side(int iu, const Eigen::Vector3d& u, int iv, const Eigen::Vector3d& v, double x,
              double y) {
  const bool flip = iv < iu;
  const Eigen::Vector3d& p = flip ? v : u;
  const Eigen::Vector3d& q = flip ? u : v;
  const double dx = q.x() - p.x(), dy = q.y() - p.y();
  // The two products are compared, not subtracted: with -march=native the compiler may fuse
  // a * b - c * d into one multiply-add, whose rounding leaves a residue of either sign where
  // the products are equal (the line exactly through a vertex), and the fan around that
  // vertex then counts the line twice or not at all.
  const double left = dx * (y - p.y()), right = dy * (x - p.x());
  int s;
  if (left > right)
    s = 1;
  else if (left < right)
    s = -1;
  else if (dy != 0)
    s = dy < 0 ? 1 : -1;
  else
    s = dx > 0 ? 1 : -1;
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
