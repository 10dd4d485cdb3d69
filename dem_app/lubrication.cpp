#include "dem_app/lubrication.hpp"

#include <algorithm>
#include <cmath>

namespace lbdem {

Lubrication::Lubrication(const LubricationLaw& law, std::vector<std::int64_t> atom_body,
                         std::vector<double> atom_radius, std::vector<LubricationWall> walls,
                         double skin)
    : law_(law),
      atom_body_(std::move(atom_body)),
      atom_radius_(std::move(atom_radius)),
      walls_(std::move(walls)),
      skin_(skin) {
  for (double r : atom_radius_) max_radius_ = std::max(max_radius_, r);
}

bool Lubrication::list_is_stale(const AtomView& a) const {
  if (a.nlocal != built_nlocal_ || static_cast<size_t>(a.nall) != built_tag_.size()) return true;
  // LAMMPS re-neighbouring reorders atoms and rebuilds the ghosts: the tags tell.
  const double limit = 0.25 * skin_ * skin_;  // moved more than half the skin
  for (int i = 0; i < a.nall; ++i) {
    if (a.tag[i] != built_tag_[static_cast<size_t>(i)]) return true;
    double d2 = 0;
    for (int d = 0; d < 3; ++d) {
      const double dx = a.x[i][d] - built_x_[static_cast<size_t>(i)][d];
      d2 += dx * dx;
    }
    if (d2 > limit) return true;
  }
  return false;
}

void Lubrication::build_list(const AtomView& a) {
  ++builds_;
  pairs_.clear();
  built_nlocal_ = a.nlocal;
  built_tag_.assign(a.tag, a.tag + a.nall);
  built_x_.resize(static_cast<size_t>(a.nall));
  for (int i = 0; i < a.nall; ++i)
    built_x_[static_cast<size_t>(i)] = {a.x[i][0], a.x[i][1], a.x[i][2]};

  // Bins of one interaction range (largest pair: 2 r_max + h_c + skin): a pair in range lies in
  // the same or an adjacent bin. (Half-range bins with a 5-bin stencil were slower here: most
  // of their 125 bins are empty at the clump-sphere densities of dense suspensions.)
  const double range = 2 * max_radius_ + law_.cutoff + skin_;
  std::array<double, 3> lo{}, hi{};
  bool any = false;
  for (int i = 0; i < a.nall; ++i) {
    if (atom_radius_[static_cast<size_t>(a.tag[i] - 1)] <= 0) continue;
    for (int d = 0; d < 3; ++d) {
      lo[d] = any ? std::min(lo[d], a.x[i][d]) : a.x[i][d];
      hi[d] = any ? std::max(hi[d], a.x[i][d]) : a.x[i][d];
    }
    any = true;
  }
  if (!any) return;
  // Dense bins as linked lists (head per bin, next per atom); the bin count is capped near the
  // atom count so sparse systems do not allocate empty space (bins then grow).
  std::array<long, 3> n{};
  double size = range;
  for (;;) {
    for (int d = 0; d < 3; ++d) n[d] = std::max(1L, static_cast<long>((hi[d] - lo[d]) / size) + 1);
    if (n[0] * n[1] * n[2] <= 8L * a.nall + 27) break;
    size *= 1.5;
  }
  auto bin_of = [&](const double* x, int d) {
    return std::min(n[d] - 1, static_cast<long>((x[d] - lo[d]) / size));
  };
  // Body and radius by atom index, so the inner loop reads contiguous memory.
  body_.resize(static_cast<size_t>(a.nall));
  radius_.resize(static_cast<size_t>(a.nall));
  for (int i = 0; i < a.nall; ++i) {
    body_[static_cast<size_t>(i)] = atom_body_[static_cast<size_t>(a.tag[i] - 1)];
    radius_[static_cast<size_t>(i)] = atom_radius_[static_cast<size_t>(a.tag[i] - 1)];
  }
  head_.assign(static_cast<size_t>(n[0] * n[1] * n[2]), -1);
  next_.assign(static_cast<size_t>(a.nall), -1);
  for (int i = a.nall - 1; i >= 0; --i) {
    if (radius_[static_cast<size_t>(i)] <= 0) continue;
    const auto b = static_cast<size_t>((bin_of(a.x[i], 0) * n[1] + bin_of(a.x[i], 1)) * n[2] +
                                       bin_of(a.x[i], 2));
    next_[static_cast<size_t>(i)] = head_[b];
    head_[b] = i;
  }
  for (int i = 0; i < a.nlocal; ++i) {
    const double ri = radius_[static_cast<size_t>(i)];
    if (ri <= 0) continue;
    const long b[3] = {bin_of(a.x[i], 0), bin_of(a.x[i], 1), bin_of(a.x[i], 2)};
    for (long p = std::max(0L, b[0] - 1); p <= std::min(n[0] - 1, b[0] + 1); ++p)
      for (long q = std::max(0L, b[1] - 1); q <= std::min(n[1] - 1, b[1] + 1); ++q)
        for (long r = std::max(0L, b[2] - 1); r <= std::min(n[2] - 1, b[2] + 1); ++r) {
          for (int j = head_[static_cast<size_t>((p * n[1] + q) * n[2] + r)]; j >= 0;
               j = next_[static_cast<size_t>(j)]) {
            if (j < a.nlocal && j <= i) continue;  // local pairs once
            const auto uj = static_cast<size_t>(j);
            if (body_[uj] == body_[static_cast<size_t>(i)]) continue;
            double d2 = 0;
            for (int d = 0; d < 3; ++d) d2 += (a.x[j][d] - a.x[i][d]) * (a.x[j][d] - a.x[i][d]);
            const double reach = ri + radius_[uj] + law_.cutoff + skin_;
            if (d2 < reach * reach) pairs_.push_back({i, j});
          }
        }
  }
}

void Lubrication::apply(const AtomView& a) {
  if (list_is_stale(a)) build_list(a);
  for (const auto& [i, j] : pairs_) {
    const double ri = atom_radius_[static_cast<size_t>(a.tag[i] - 1)];
    const double rj = atom_radius_[static_cast<size_t>(a.tag[j] - 1)];
    double n[3], dist2 = 0;
    for (int d = 0; d < 3; ++d) {
      n[d] = a.x[j][d] - a.x[i][d];
      dist2 += n[d] * n[d];
    }
    const double reach = ri + rj + law_.cutoff;
    if (dist2 >= reach * reach) continue;  // most listed pairs: inside the skin only
    const double dist = std::sqrt(dist2);
    const double c = lubrication_resistance(law_, ri, rj, dist - ri - rj);
    if (c == 0 || dist == 0) continue;
    double un = 0;  // approach speed (v_i - v_j) . n
    for (int d = 0; d < 3; ++d) {
      n[d] /= dist;
      un += (a.v[i][d] - a.v[j][d]) * n[d];
    }
    for (int d = 0; d < 3; ++d) {
      a.f[i][d] -= c * un * n[d];
      if (j < a.nlocal) a.f[j][d] += c * un * n[d];
    }
  }
  for (int i = 0; i < a.nlocal; ++i) {
    const double r = atom_radius_[static_cast<size_t>(a.tag[i] - 1)];
    if (r <= 0) continue;
    for (const auto& w : walls_) {
      // n points from the sphere to the wall.
      const double side = w.lower ? -1.0 : 1.0;
      const double gap = side * (w.position - a.x[i][w.axis]) - r;
      const double c = lubrication_resistance(law_, r, 0.0, gap);
      if (c == 0) continue;
      a.f[i][w.axis] -= c * a.v[i][w.axis];
      // Sliding and rolling parallel to the wall (lubrication_law.hpp): with n = side e_axis,
      // the parts of v and omega along the other two axes.
      const SlidingResistance s = wall_sliding_resistance(law_, r, gap);
      const int p = (w.axis + 1) % 3, q = (w.axis + 2) % 3;
      // (W x n) and (n x U) for n = side e_axis, restricted to the wall's plane.
      const double wxn_p = a.omega[i][q] * side, wxn_q = -a.omega[i][p] * side;
      const double nxu_p = -side * a.v[i][q], nxu_q = side * a.v[i][p];
      a.f[i][p] -= s.translation * a.v[i][p] + s.coupling * wxn_p;
      a.f[i][q] -= s.translation * a.v[i][q] + s.coupling * wxn_q;
      a.torque[i][p] -= s.coupling * nxu_p + s.rotation * a.omega[i][p];
      a.torque[i][q] -= s.coupling * nxu_q + s.rotation * a.omega[i][q];
    }
  }
}

}  // namespace lbdem
