#include "dem_app/lubrication/lubrication.hpp"

#include <algorithm>
#include <cmath>

namespace lbdem {

namespace {

// A cell's body in the search: the body id when all its atoms are of one body (most cells of
// a dense clump suspension: same-body pairs are the bulk of the candidates), else these.
constexpr std::int64_t kNoBody = -1, kMixed = -2;

}  // namespace

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

  // Cells of one interaction range (largest pair: 2 r_max + h_c + skin): a pair in range lies
  // in the same or an adjacent cell, so each cell is paired with itself and 13 of its 26
  // neighbours (a half stencil: every unordered pair of cells once). The atoms are sorted by
  // cell into contiguous arrays (position, radius, body), so the pair loops read memory in
  // order instead of chasing a linked list through LAMMPS's arrays; this, and testing each
  // pair of atoms once, is what brings the search down to the contacts' own cost
  // (docs/lubrication.md, "Cost").
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
  // The cell count is capped near the atom count so sparse systems do not allocate empty
  // space (cells then grow).
  std::array<long, 3> n{};
  double size = range;
  for (;;) {
    for (int d = 0; d < 3; ++d) n[d] = std::max(1L, static_cast<long>((hi[d] - lo[d]) / size) + 1);
    if (n[0] * n[1] * n[2] <= 8L * a.nall + 27) break;
    size *= 1.5;
  }
  auto cell_of = [&](const double* x) {
    long c = 0;
    for (int d = 0; d < 3; ++d)
      c = c * n[d] + std::min(n[d] - 1, static_cast<long>((x[d] - lo[d]) / size));
    return static_cast<size_t>(c);
  };
  // Counting sort by cell: cell c holds sorted entries [start_[c], start_[c + 1]).
  const auto cells = static_cast<size_t>(n[0] * n[1] * n[2]);
  start_.assign(cells + 1, 0);
  cell_.resize(static_cast<size_t>(a.nall));
  for (int i = 0; i < a.nall; ++i) {
    const bool takes_part = atom_radius_[static_cast<size_t>(a.tag[i] - 1)] > 0;
    cell_[static_cast<size_t>(i)] = takes_part ? cell_of(a.x[i]) : cells;
    if (takes_part) ++start_[cell_[static_cast<size_t>(i)] + 1];
  }
  for (size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  sorted_.resize(start_[cells]);
  fill_ = start_;
  has_local_.assign(cells, 0);
  cell_body_.assign(cells, kNoBody);
  for (int i = 0; i < a.nall; ++i) {
    const size_t c = cell_[static_cast<size_t>(i)];
    if (c == cells) continue;
    const std::int64_t t = a.tag[i] - 1;
    sorted_[fill_[c]++] = {{a.x[i][0], a.x[i][1], a.x[i][2]},
                           atom_radius_[static_cast<size_t>(t)],
                           atom_body_[static_cast<size_t>(t)],
                           i};
    if (i < a.nlocal) has_local_[c] = 1;
    const std::int64_t b = atom_body_[static_cast<size_t>(t)];
    cell_body_[c] = cell_body_[c] == kNoBody || cell_body_[c] == b ? b : kMixed;
  }
  // Pairs between the entries of cells c and e (c == e: each pair once); at least one atom
  // local, the local one first.
  const double extra = law_.cutoff + skin_;
  auto pair_cells = [&](size_t c, size_t e) {
    for (size_t p = start_[c]; p < start_[c + 1]; ++p) {
      const SortedAtom& u = sorted_[p];
      for (size_t q = c == e ? p + 1 : start_[e]; q < start_[e + 1]; ++q) {
        const SortedAtom& w = sorted_[q];
        if (u.body == w.body) continue;
        const double dx = w.x[0] - u.x[0], dy = w.x[1] - u.x[1], dz = w.x[2] - u.x[2];
        const double reach = u.radius + w.radius + extra;
        if (dx * dx + dy * dy + dz * dz >= reach * reach) continue;
        if (u.index < a.nlocal)
          pairs_.push_back({u.index, w.index});
        else if (w.index < a.nlocal)
          pairs_.push_back({w.index, u.index});
      }
    }
  };
  // The 13 neighbours of the half stencil: offsets that are lexicographically positive.
  for (long p = 0; p < n[0]; ++p)
    for (long q = 0; q < n[1]; ++q)
      for (long r = 0; r < n[2]; ++r) {
        const auto c = static_cast<size_t>((p * n[1] + q) * n[2] + r);
        if (start_[c] == start_[c + 1]) continue;
        // A cell inside one body has no pair of its own.
        if (has_local_[c] && cell_body_[c] == kMixed) pair_cells(c, c);
        for (long dp = 0; dp <= 1; ++dp)
          for (long dq = dp == 0 ? 0 : -1; dq <= 1; ++dq)
            for (long dr = dp == 0 && dq == 0 ? 1 : -1; dr <= 1; ++dr) {
              const long pp = p + dp, qq = q + dq, rr = r + dr;
              if (pp >= n[0] || qq < 0 || qq >= n[1] || rr < 0 || rr >= n[2]) continue;
              const auto e = static_cast<size_t>((pp * n[1] + qq) * n[2] + rr);
              if ((has_local_[c] || has_local_[e]) &&
                  (cell_body_[c] != cell_body_[e] || cell_body_[c] == kMixed))
                pair_cells(c, e);
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
    const double dist = std::sqrt(dist2), gap = dist - ri - rj;
    const double c = lubrication_resistance(law_, ri, rj, gap);
    if (c == 0 || dist == 0) continue;
    Vec3 d{}, du{};
    double un = 0;  // approach speed (v_i - v_j) . d
    for (int k = 0; k < 3; ++k) {
      d[k] = n[k] / dist;
      du[k] = a.v[i][k] - a.v[j][k];
      un += du[k] * d[k];
    }
    // Sliding and rolling (lubrication_law.hpp): the force on j is the opposite of i's.
    const PairSlidingLoads s = pair_sliding_loads(pair_sliding_resistance(law_, ri, rj, gap), d, du,
                                                  {a.omega[i][0], a.omega[i][1], a.omega[i][2]},
                                                  {a.omega[j][0], a.omega[j][1], a.omega[j][2]});
    for (int k = 0; k < 3; ++k) {
      const double f = -c * un * d[k] + s.force1[k];
      a.f[i][k] += f;
      a.torque[i][k] += s.torque1[k];
      if (j < a.nlocal) {
        a.f[j][k] -= f;
        a.torque[j][k] += s.torque2[k];
      }
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
