#include "fluid_app/hlbm/body_field.hpp"

#include "fluid_app/lattice/d3q19.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace lbdem::hlbm {

namespace {

// A body whose surface moves by less than this (cells) since the last update is updated
// incrementally. Its porous band is about 1.5 cells wide (|distance| < 3 h / 2 from the
// voxel surface, h = dx / 2): no cell can go from interior to fluid (or back) without being
// in the old or the new band, and every piece of the new band overlaps the old band.
// Larger moves re-embed the body from scratch.
constexpr double kMaxIncrementalMove = 0.5;

std::array<std::uint16_t, 3> local(int x, int y, int z) {
  return {static_cast<std::uint16_t>(x), static_cast<std::uint16_t>(y),
          static_cast<std::uint16_t>(z)};
}

}  // namespace

template <class T>
BodyField<T>::BodyField(std::span<const Shape> shapes, const Subdomain& sub,
                        const LatticeFrame& frame, PorousField<T>& field, PorosityLookup lookup)
    : lookup_(lookup), sub_(sub), frame_(frame), field_(field) {
  const auto cells = static_cast<std::size_t>(sub.box.cells_with_ghosts());
  if (cells >= std::numeric_limits<std::uint32_t>::max() ||
      std::max({sub.box.n[0], sub.box.n[1], sub.box.n[2]}) + 1 >
          std::numeric_limits<std::uint16_t>::max())
    throw std::invalid_argument(
        "BodyField: local box too large for 32-bit cell indices and 16-bit coordinates");
  if (!(frame.units.dx > 0) || !(frame.units.dt > 0))
    throw std::invalid_argument("BodyField: unit converter without a positive dx and dt");
  field_.d.assign(cells, 1.0f);
  field_.body.assign(cells, -1);
  field_.bodies.clear();
  field_.active = false;
  shapes_.reserve(shapes.size());
  // The stencil spacing dx / 2 is a whole number of voxels (2 for the scenes' reference
  // lattice of dx / 4, shape.hpp).
  for (const Shape& s : shapes) {
    const double step = frame.units.dx / (2 * s.voxels.h);
    if (!(std::abs(step - std::round(step)) < 1e-6 && std::round(step) >= 1))
      throw std::invalid_argument("BodyField: shape '" + s.name + "' has voxels of " +
                                  std::to_string(s.voxels.h) +
                                  " m; the stencil spacing dx / 2 must be a whole number of them");
    shapes_.emplace_back(s.voxels, static_cast<int>(std::lround(step)));
  }
}

template <class T>
std::int32_t BodyField<T>::slot_of(std::int64_t id) const {
  const auto it = slots_.find(id);
  return it == slots_.end() ? -1 : it->second;
}

template <class T>
float BodyField<T>::body_porosity(std::int64_t id, CellIndex cell) const {
  const std::int32_t slot = slot_of(id);
  if (slot < 0) return 1.0f;
  const Tracked& t = tracked_[static_cast<std::size_t>(slot)];
  const auto l = sub_.box.coords(cell);
  Eigen::Vector3d r;
  for (int a = 0; a < 3; ++a) r[a] = sub_.min_image(a, sub_.position(a, l[a]) - t.x[a]);
  return porosity(t, r);
}

template <class T>
void BodyField<T>::set_pose(Tracked& t, const BodyState& s) const {
  const double dx = frame_.units.dx;
  for (int a = 0; a < 3; ++a) {
    double x = (s.x[a] - frame_.origin[a]) / dx;
    const double len = sub_.box.global[a];
    if (sub_.periodic[a]) x = wrap_periodic(x, len);
    t.x[a] = x;
  }
  const Eigen::Quaterniond q(s.q[0], s.q[1], s.q[2], s.q[3]);
  if (!(q.norm() > 0.5))
    throw std::invalid_argument("BodyField: body " + std::to_string(s.id) +
                                " has a degenerate orientation quaternion");
  t.rot = q.normalized().toRotationMatrix();
  t.to_ref = t.rot.transpose() * (dx / shapes_[static_cast<std::size_t>(t.shape)].spacing());
  // (dx / 2) c_i in lattice units is c_i / 2; mapped by to_ref = rot^T dx / h_voxel it is
  // step rot^T c_i, step = dx / (2 h_voxel).
  const double step = shapes_[static_cast<std::size_t>(t.shape)].step();
  for (std::size_t i = 0; i < d3q19::c.size(); ++i) {
    const Eigen::Vector3d o =
        t.rot.transpose() *
        Eigen::Vector3d(step * d3q19::c[i][0], step * d3q19::c[i][1], step * d3q19::c[i][2]);
    t.stencil.x[i] = o.x();
    t.stencil.y[i] = o.y();
    t.stencil.z[i] = o.z();
  }
  t.stencil.set_extent();
}

// Paper, appendix "Representation of a particle in the fluid": the node at minimum-image
// offset r (lattice units) from the centre is mapped into the shape frame (rotated by q^-1)
// and gets the smoothed reference porosity there. The map p = to_ref r + shift is written as
// explicit fused multiply-adds in a fixed order, so that no compiler contraction can give one
// path (band update, full scan, body_porosity) other bits than another.
template <class T>
float BodyField<T>::porosity(const Tracked& t, const Eigen::Vector3d& r) const {
  const ReferencePorosity& ref = shapes_[static_cast<std::size_t>(t.shape)];
  const Eigen::Matrix3d& m = t.to_ref;
  Eigen::Vector3d p;
  for (int a = 0; a < 3; ++a)
    p[a] =
        std::fma(m(a, 0), r[0], std::fma(m(a, 1), r[1], std::fma(m(a, 2), r[2], ref.shift()[a])));
  return static_cast<float>(lookup_ == PorosityLookup::nearest ? ref.nearest(p, t.stencil)
                                                               : ref.at(p));
}

// The offsets are the same doubles body_porosity() computes, so every path gives a cell the
// same porosity bit for bit.
template <class T>
void BodyField<T>::tabulate_offsets(const Tracked& t) {
  for (int a = 0; a < 3; ++a) {
    rel_[a].resize(static_cast<std::size_t>(sub_.box.n[a]) + 2);
    for (int l = 0; l <= sub_.box.n[a] + 1; ++l)
      rel_[a][static_cast<std::size_t>(l)] = sub_.min_image(a, sub_.position(a, l) - t.x[a]);
  }
}

// Queues the window cells `bits` (one word per 64 cells) of window row `row` for evaluation,
// mapped into the reference lattice as porosity() maps them: p = to_ref r + shift as the same
// fused multiply-adds, the y and z terms once per row.
template <class T>
void BodyField<T>::queue_row(const Tracked& t, std::size_t row, const std::uint64_t* bits) {
  const Window& w = window_;
  const std::size_t ny = w.l[1].size();
  const int y = w.l[1][row % ny], z = w.l[2][row / ny];
  const Eigen::Matrix3d& m = t.to_ref;
  const Eigen::Vector3d& shift = shapes_[static_cast<std::size_t>(t.shape)].shift();
  const double r1 = rel_[1][static_cast<std::size_t>(y)], r2 = rel_[2][static_cast<std::size_t>(z)];
  const double b0 = std::fma(m(0, 1), r1, std::fma(m(0, 2), r2, shift[0]));
  const double b1 = std::fma(m(1, 1), r1, std::fma(m(1, 2), r2, shift[1]));
  const double b2 = std::fma(m(2, 1), r1, std::fma(m(2, 2), r2, shift[2]));
  const auto first = static_cast<std::uint32_t>(sub_.box.index(0, y, z));
  std::size_t count = batch_.count, added = 0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(w.words); ++k)
    added += static_cast<std::size_t>(std::popcount(bits[k]));
  queue_.resize(count + added);
  batch_.resize(count + added);
  // Ask now for the field's lines (both arrays) under the queued cells, from the first to the
  // last: the interior map reads them once the batch is looked up, and on a large lattice they
  // are rarely in cache. The window's x list is ascending.
  if (added) {
    std::size_t k0 = 0, k1 = static_cast<std::size_t>(w.words) - 1;
    while (!bits[k0]) ++k0;
    while (!bits[k1]) --k1;
    const int x0 = w.l[0][64 * k0 + static_cast<std::size_t>(std::countr_zero(bits[k0]))];
    const int x1 = w.l[0][64 * k1 + 63 - static_cast<std::size_t>(std::countl_zero(bits[k1]))];
    for (int x = x0;; x += 16) {  // 16 cells: one 64-byte line of either array
      const int c = std::min(x, x1);
      __builtin_prefetch(&field_.d[first + static_cast<std::uint32_t>(c)]);
      __builtin_prefetch(&field_.body[first + static_cast<std::uint32_t>(c)]);
      if (c == x1) break;
    }
  }
  for (std::size_t k = 0; k < static_cast<std::size_t>(w.words); ++k)
    for (std::uint64_t left = bits[k]; left; left &= left - 1, ++count) {
      const std::size_t i = 64 * k + static_cast<std::size_t>(std::countr_zero(left));
      const int x = w.l[0][i];
      const double r0 = rel_[0][static_cast<std::size_t>(x)];
      batch_.x[count] = std::fma(m(0, 0), r0, b0);
      batch_.y[count] = std::fma(m(1, 0), r0, b1);
      batch_.z[count] = std::fma(m(2, 0), r0, b2);
      queue_.cell[count] = first + static_cast<std::uint32_t>(x);
      queue_.row[count] = static_cast<std::uint32_t>(row);
      queue_.i[count] = static_cast<std::uint32_t>(i);
    }
}

// Porosity of the queued cells for body `slot` (into batch_.d), and the interior map.
template <class T>
void BodyField<T>::evaluate_queue(std::int32_t slot, UpdateStats& stats) {
  const Tracked& t = tracked_[static_cast<std::size_t>(slot)];
  const ReferencePorosity& ref = shapes_[static_cast<std::size_t>(t.shape)];
  const std::size_t n = batch_.count;
  stats.evaluated += n;
  if (lookup_ == PorosityLookup::nearest) {
    ref.nearest(batch_, t.stencil);
  } else {
    batch_.mixed_count = n;
    for (std::size_t k = 0; k < n; ++k) {
      batch_.d[k] =
          static_cast<float>(ref.at(Eigen::Vector3d(batch_.x[k], batch_.y[k], batch_.z[k])));
      batch_.mixed[k] = static_cast<std::uint32_t>(k);
    }
  }
  // Most cells are neither interior now nor held as an interior before: one read decides.
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t cell = queue_.cell[k];
    const float d = batch_.d[k];
    if (d != 0.0f && field_.d[cell] != 0.0f) continue;
    mark_interior(slot, cell, d, stats);
  }
}

// A cell whose interior owner changes is reset by reset_touched(); the band cells (old and new)
// are added by the callers. The interior map is the field itself: d = 0 exactly where a body's
// interior covers the cell (band cells have 0 < d < 1), with that body's index, so no per-cell
// map of its own is kept (4 B per cell, docs/performance.md "Memory per cell"). The field is
// read by the kernel only after the update, once combine() has run.
template <class T>
void BodyField<T>::mark_interior(std::int32_t slot, std::uint32_t cell, float d,
                                 UpdateStats& stats) {
  float& fd = field_.d[cell];
  std::int32_t& fb = field_.body[cell];
  const std::int32_t in = fd == 0.0f ? fb : -1;
  if (d == 0.0f) {
    if (in != slot) {
      if (in >= 0) ++stats.interior_conflicts;
      fd = 0.0f;
      fb = slot;
      touched_.push_back(cell);
    }
  } else if (in == slot) {
    fd = 1.0f;
    fb = -1;
    touched_.push_back(cell);
  }
}

// The support radius of a body in cells, plus one cell (far above the round-off of an offset).
template <class T>
double BodyField<T>::reach(const Tracked& t) const {
  return shapes_[static_cast<std::size_t>(t.shape)].support_radius() / frame_.units.dx + 1.0;
}

// Local coordinates per axis within the reach of a body. Reads the offsets tabulated for t
// (tabulate_offsets).
template <class T>
std::array<std::vector<int>, 3> BodyField<T>::support(const Tracked& t) const {
  const double radius = reach(t);
  std::array<std::vector<int>, 3> lists;
  for (int a = 0; a < 3; ++a)
    for (int l = 0; l <= sub_.box.n[a] + 1; ++l)
      if (std::abs(rel_[a][static_cast<std::size_t>(l)]) <= radius) lists[a].push_back(l);
  return lists;
}

// Embeds a body from scratch: every stored cell within its support (cost ~ volume; used
// when a body appears or jumps), queued row by row, so the band comes out in cell order.
template <class T>
void BodyField<T>::scan(std::int32_t slot, std::vector<BandCell>& band, UpdateStats& stats) {
  const Tracked& t = tracked_[static_cast<std::size_t>(slot)];
  tabulate_offsets(t);
  open_window(support(t));
  ++stats.full_scans;
  const Window& w = window_;
  const std::size_t nx = w.l[0].size(), ny = w.l[1].size();
  std::vector<std::uint64_t> all(static_cast<std::size_t>(w.words), 0);
  for (std::size_t i = 0; i < nx; ++i) all[i / 64] |= std::uint64_t{1} << (i % 64);
  batch_.resize(0);
  for (std::size_t row = 0; row < w.rows; ++row) queue_row(t, row, all.data());
  evaluate_queue(slot, stats);
  for (std::uint32_t k : batch_.mixed_nodes()) {  // in queue order, so in cell order
    const float d = batch_.d[k];
    if (d > 0.0f && d < 1.0f) {
      const std::size_t row = queue_.row[k];
      band.push_back({d, local(w.l[0][queue_.i[k]], w.l[1][row % ny], w.l[2][row / ny])});
      touched_.push_back(queue_.cell[k]);
    }
  }
}

// Takes a body out of the field at its last pose: its band cells and the interior cells it
// holds (found by a scan of its support, cost ~ volume; bodies leave a rank rarely).
template <class T>
void BodyField<T>::remove(std::int32_t slot, UpdateStats& stats) {
  Tracked& t = tracked_[static_cast<std::size_t>(slot)];
  for (const BandCell& b : t.band) touched_.push_back(static_cast<std::uint32_t>(b.cell(sub_.box)));
  t.band.clear();
  tabulate_offsets(t);
  const auto lists = support(t);
  ++stats.full_scans;
  for (int z : lists[2])
    for (int y : lists[1])
      for (int x : lists[0]) {
        const auto c = static_cast<std::uint32_t>(sub_.box.index(x, y, z));
        if (field_.d[c] == 0.0f && field_.body[c] == slot) {  // its interior
          field_.d[c] = 1.0f;
          field_.body[c] = -1;
          touched_.push_back(c);
        }
      }
}

template <class T>
void BodyField<T>::open_window(const std::array<std::vector<int>, 3>& lists) {
  Window& w = window_;
  for (int a = 0; a < 3; ++a) {
    w.l[a] = lists[a];
    w.inv[a].assign(static_cast<std::size_t>(sub_.box.n[a]) + 2, -1);
    for (std::size_t i = 0; i < lists[a].size(); ++i)
      w.inv[a][static_cast<std::size_t>(lists[a][i])] = static_cast<int>(i);
  }
  const std::size_t nx = lists[0].size();
  w.words = static_cast<int>((nx + 63) / 64);
  w.rows = lists[1].size() * lists[2].size();
  const auto words = static_cast<std::size_t>(w.words);
  w.adjacent_up.assign(words, 0);
  w.adjacent_down.assign(words, 0);
  for (std::size_t i = 0; i + 1 < nx; ++i)
    if (lists[0][i + 1] == lists[0][i] + 1) {
      w.adjacent_up[(i + 1) / 64] |= std::uint64_t{1} << ((i + 1) % 64);
      w.adjacent_down[i / 64] |= std::uint64_t{1} << (i % 64);
    }
  for (auto* bits : {&w.evaluated, &w.band, &w.old, &w.frontier, &w.candidates})
    bits->assign(w.rows * words, 0);
  w.in_frontier.assign(w.rows, 0);
  w.in_candidates.assign(w.rows, 0);
  w.frontier_rows.clear();
  w.candidate_rows.clear();
  w.grown.resize(words);
  w.fresh.resize(words);
  w.d.resize(w.rows * nx);
}

// The surface-only update (paper: "only the nodes currently covered by a body and a
// surrounding growth layer have to be revisited"). The cells evaluated: every 26-neighbour of
// an old band cell (the old band itself among them) and, grown from there, every 26-neighbour of
// every new band cell. With a move below kMaxIncrementalMove (a third of the ~1.5-cell band
// width) every piece of the new band overlaps the old band, except pieces that enter the
// stored box from outside: those contain a cell of the box's outermost layer, so when the
// body's support crosses that layer its cells there within the body's reach are evaluated too.
// Interior cells (d = 0) not reached keep their value: they cannot have left the interior without
// entering the new band.
//
// The growth runs on bit rows of the body's window, a round at a time: a set of cells is
// dilated by one cell (shifts along x, neighbouring rows in y and z, masked where the lists
// skip cells) and the cells of that not yet evaluated are evaluated as one batch. The first
// round dilates the old band; each later one the band cells found in the round before that
// were not in the old band (the neighbours of old band cells are all evaluated already). A
// band cell's neighbours are within reach + 1 cell of the centre on every axis, so inside the
// window. The new band comes out in cell order, as from a full scan.
template <class T>
void BodyField<T>::follow_band(std::int32_t slot, std::vector<BandCell>& band, UpdateStats& stats) {
  const LocalBox& box = sub_.box;
  const Tracked& t = tracked_[static_cast<std::size_t>(slot)];
  tabulate_offsets(t);
  open_window(support(t));
  Window& w = window_;
  const std::size_t nx = w.l[0].size(), ny = w.l[1].size(), nz = w.l[2].size();
  const auto words = static_cast<std::size_t>(w.words);

  auto mark = [&](std::vector<std::uint64_t>& bits, std::vector<std::uint8_t>& listed,
                  std::vector<std::size_t>& rows, std::size_t i, std::size_t row) {
    bits[row * words + i / 64] |= std::uint64_t{1} << (i % 64);
    if (!listed[row]) {
      listed[row] = 1;
      rows.push_back(row);
    }
  };

  // Seeds: the old band (inside the window: it moved by less than a cell) is the first
  // frontier; the box's outermost layer, where the support reaches it, is evaluated as is.
  // The band is in cell order, so runs of it share a word: each word is written once.
  std::size_t run_word = 0;
  std::uint64_t run_bits = 0;
  auto flush = [&]() {
    if (!run_bits) return;
    w.old[run_word] |= run_bits;
    w.frontier[run_word] |= run_bits;
    const std::size_t row = run_word / words;
    if (!w.in_frontier[row]) {
      w.in_frontier[row] = 1;
      w.frontier_rows.push_back(row);
    }
  };
  for (const BandCell& b : t.band) {
    const int i = w.inv[0][b.l[0]], j = w.inv[1][b.l[1]], k = w.inv[2][b.l[2]];
    if (i < 0 || j < 0 || k < 0)
      throw std::logic_error("BodyField: a band cell of body " + std::to_string(t.id) +
                             " lies beyond its reach after an incremental move");
    const auto x = static_cast<std::size_t>(i);
    const std::size_t row = static_cast<std::size_t>(j) + ny * static_cast<std::size_t>(k);
    const std::size_t word = row * words + x / 64;
    if (word != run_word) {
      flush();
      run_word = word;
      run_bits = 0;
    }
    run_bits |= std::uint64_t{1} << (x % 64);
  }
  flush();
  // The outermost layer, only its cells within the reach of the centre: beyond the support
  // radius the porosity is 1 at this pose, and was at the last one (it moved by less than a
  // cell), so no band piece and no interior can be there. Cells i_first .. i_last - 1 of a row.
  const double reach = this->reach(t), reach2 = reach * reach;
  // Squared offsets from the centre per window index (axis a: r2[a]).
  for (int a = 0; a < 3; ++a) {
    const std::vector<int>& l = w.l[static_cast<std::size_t>(a)];
    std::vector<double>& r2 = w.r2[static_cast<std::size_t>(a)];
    r2.resize(l.size());
    for (std::size_t i = 0; i < l.size(); ++i) {
      const double r = rel_[static_cast<std::size_t>(a)][static_cast<std::size_t>(l[i])];
      r2[i] = r * r;
    }
  }
  const std::vector<double>&rx2 = w.r2[0], &ry2 = w.r2[1], &rz2 = w.r2[2];
  auto face_cells = [&](std::size_t jy, std::size_t jz, std::size_t i_first, std::size_t i_last) {
    const double rest = reach2 - ry2[jy] - rz2[jz];
    const std::size_t row = jy + ny * jz;
    std::uint64_t any = 0;
    for (std::size_t k = i_first / 64; 64 * k < i_last; ++k) {
      std::uint64_t bits = 0;
      for (std::size_t i = std::max(i_first, 64 * k); i < std::min(i_last, 64 * k + 64); ++i)
        bits |= std::uint64_t{rx2[i] <= rest} << (i % 64);
      w.candidates[row * words + k] |= bits;
      any |= bits;
    }
    if (any && !w.in_candidates[row]) {
      w.in_candidates[row] = 1;
      w.candidate_rows.push_back(row);
    }
  };
  for (int face : {0, box.n[0] + 1})
    if (const int wf = w.inv[0][static_cast<std::size_t>(face)]; wf >= 0) {
      const auto i = static_cast<std::size_t>(wf);
      for (std::size_t jz = 0; jz < nz; ++jz)
        for (std::size_t jy = 0; jy < ny; ++jy)
          if (rx2[i] + ry2[jy] + rz2[jz] <= reach2) face_cells(jy, jz, i, i + 1);
    }
  for (int face : {0, box.n[1] + 1})
    if (const int wf = w.inv[1][static_cast<std::size_t>(face)]; wf >= 0)
      for (std::size_t jz = 0; jz < nz; ++jz) face_cells(static_cast<std::size_t>(wf), jz, 0, nx);
  for (int face : {0, box.n[2] + 1})
    if (const int wf = w.inv[2][static_cast<std::size_t>(face)]; wf >= 0)
      for (std::size_t jy = 0; jy < ny; ++jy) face_cells(jy, static_cast<std::size_t>(wf), 0, nx);

  std::vector<std::uint64_t>& grown = w.grown;
  for (;;) {
    // Dilate the frontier into the candidates.
    for (std::size_t row : w.frontier_rows) {
      w.in_frontier[row] = 0;
      const std::size_t base = row * words;
      for (std::size_t k = 0; k < words; ++k) {
        const std::uint64_t v = w.frontier[base + k];
        const std::uint64_t up = (v << 1) | (k > 0 ? w.frontier[base + k - 1] >> 63 : 0);
        const std::uint64_t down = (v >> 1) | (k + 1 < words ? w.frontier[base + k + 1] << 63 : 0);
        grown[k] = v | (up & w.adjacent_up[k]) | (down & w.adjacent_down[k]);
      }
      for (std::size_t k = 0; k < words; ++k) w.frontier[base + k] = 0;
      const std::size_t jy = row % ny, jz = row / ny;
      for (int dz = -1; dz <= 1; ++dz) {
        const std::size_t tz = jz + static_cast<std::size_t>(dz);
        if (tz >= nz || w.l[2][tz] != w.l[2][jz] + dz) continue;
        for (int dy = -1; dy <= 1; ++dy) {
          const std::size_t ty = jy + static_cast<std::size_t>(dy);
          if (ty >= ny || w.l[1][ty] != w.l[1][jy] + dy) continue;
          const std::size_t target = ty + ny * tz;
          for (std::size_t k = 0; k < words; ++k) w.candidates[target * words + k] |= grown[k];
          if (!w.in_candidates[target]) {
            w.in_candidates[target] = 1;
            w.candidate_rows.push_back(target);
          }
        }
      }
    }
    w.frontier_rows.clear();
    if (w.candidate_rows.empty()) break;

    // Evaluate the candidates not evaluated yet.
    batch_.resize(0);
    for (std::size_t row : w.candidate_rows) {
      w.in_candidates[row] = 0;
      bool any = false;
      for (std::size_t k = 0; k < words; ++k) {
        const std::size_t word = row * words + k;
        w.fresh[k] = w.candidates[word] & ~w.evaluated[word];
        w.candidates[word] = 0;
        w.evaluated[word] |= w.fresh[k];
        any = any || w.fresh[k];
      }
      if (any) queue_row(t, row, w.fresh.data());
    }
    w.candidate_rows.clear();
    evaluate_queue(slot, stats);

    // Band cells join the band; those not in the old band are the next frontier.
    for (std::uint32_t k : batch_.mixed_nodes()) {
      const float d = batch_.d[k];
      if (!(d > 0.0f && d < 1.0f)) continue;
      const std::size_t row = queue_.row[k], i = queue_.i[k];
      const std::size_t word = row * words + i / 64;
      const std::uint64_t bit = std::uint64_t{1} << (i % 64);
      w.d[row * nx + i] = d;
      w.band[word] |= bit;
      if (!(w.old[word] & bit)) mark(w.frontier, w.in_frontier, w.frontier_rows, i, row);
    }
  }

  // The new band, and the old band cells that left it: reset_touched() resets both.
  for (std::size_t row = 0; row < w.rows; ++row) {
    const int y = w.l[1][row % ny], z = w.l[2][row / ny];
    for (std::size_t k = 0; k < words; ++k) {
      const std::size_t word = row * words + k;
      for (std::uint64_t bits = w.band[word]; bits; bits &= bits - 1) {
        const std::size_t i = 64 * k + static_cast<std::size_t>(std::countr_zero(bits));
        const auto c = static_cast<std::uint32_t>(box.index(w.l[0][i], y, z));
        band.push_back({w.d[row * nx + i], local(w.l[0][i], y, z)});
        touched_.push_back(c);
      }
      for (std::uint64_t bits = w.old[word] & ~w.band[word]; bits; bits &= bits - 1) {
        const std::size_t i = 64 * k + static_cast<std::size_t>(std::countr_zero(bits));
        touched_.push_back(static_cast<std::uint32_t>(box.index(w.l[0][i], y, z)));
      }
    }
  }
}

// Upper bound (cells) of how far any point of the body's surface moved: the centre's move
// plus the chord 2 sin(theta / 2) r of the rotation R' R^T (angle theta) at the largest
// surface radius r.
template <class T>
double BodyField<T>::displacement(const Tracked& t, const Tracked& next) const {
  Eigen::Vector3d dx;
  for (int a = 0; a < 3; ++a) dx[a] = sub_.min_image(a, next.x[a] - t.x[a]);
  const double cos_theta =
      std::clamp(((next.rot * t.rot.transpose()).trace() - 1.0) / 2.0, -1.0, 1.0);
  const double chord = std::sqrt(2.0 * (1.0 - cos_theta));  // = 2 sin(theta / 2)
  const double arm = shapes_[static_cast<std::size_t>(t.shape)].surface_radius() / frame_.units.dx;
  return dx.norm() + chord * arm;
}

// The cells the body just updated touched (its old and new band, its interior changes) start
// over from the interior map: d = 0 keeps its body (written by mark_interior(), of this body or
// another), the rest become fluid with body -1, to be lowered by the bands in combine(). Done
// per body while the cells' lines are in cache. Later bodies of the update read only whether a
// cell is d = 0 (mark_interior()), which this does not change.
template <class T>
void BodyField<T>::reset_touched() {
  for (std::uint32_t c : touched_)
    if (field_.d[c] != 0.0f) {
      field_.d[c] = 1.0f;
      field_.body[c] = -1;
    }
  touched_.clear();
}

// Two-body rule: a cell covered by several bodies gets the smallest porosity, d = min_k d_k,
// and the index of the body with that porosity (the most solid one; ties: smallest id). Every
// band cell was reset by reset_touched(); every band of every body lowers them.
template <class T>
void BodyField<T>::combine(std::span<const std::int32_t> order) {
  // The cells lie scattered over the field, beyond what the hardware prefetches: ask for the
  // lines of the cell kAhead places further.
  constexpr std::size_t kAhead = 16;
  for (std::int32_t slot : order) {
    const std::vector<BandCell>& band = tracked_[static_cast<std::size_t>(slot)].band;
    for (std::size_t k = 0; k < band.size(); ++k) {
      if (k + kAhead < band.size()) {
        const CellIndex ahead = band[k + kAhead].cell(sub_.box);
        __builtin_prefetch(&field_.d[ahead], 1);
        __builtin_prefetch(&field_.body[ahead], 1);
      }
      const BandCell& b = band[k];
      const CellIndex c = b.cell(sub_.box);
      if (b.d < field_.d[c]) {
        field_.d[c] = b.d;
        field_.body[c] = slot;
      }
    }
  }
}

template <class T>
UpdateStats BodyField<T>::update(std::span<const BodyState> states, UpdateMode mode) {
  UpdateStats stats;
  touched_.clear();

  std::vector<std::size_t> by_id(states.size());
  std::iota(by_id.begin(), by_id.end(), std::size_t{0});
  std::sort(by_id.begin(), by_id.end(),
            [&](std::size_t a, std::size_t b) { return states[a].id < states[b].id; });
  std::vector<std::int64_t> ids(by_id.size());
  for (std::size_t i = 0; i < by_id.size(); ++i) {
    const BodyState& s = states[by_id[i]];
    ids[i] = s.id;
    if (i > 0 && ids[i - 1] == s.id)
      throw std::invalid_argument("BodyField: body " + std::to_string(s.id) +
                                  " delivered twice in one update");
    if (s.shape < 0 || static_cast<std::size_t>(s.shape) >= shapes_.size())
      throw std::invalid_argument("BodyField: body " + std::to_string(s.id) + " has shape " +
                                  std::to_string(s.shape) + " but the catalogue has " +
                                  std::to_string(shapes_.size()) + " shapes");
  }

  // Bodies that are gone.
  for (std::size_t slot = 0; slot < tracked_.size(); ++slot) {
    Tracked& t = tracked_[slot];
    if (t.id < 0 || std::binary_search(ids.begin(), ids.end(), t.id)) continue;
    if (mode == UpdateMode::incremental) {
      remove(static_cast<std::int32_t>(slot), stats);
      reset_touched();
    }
    slots_.erase(t.id);
    t = Tracked{};
    field_.bodies.set(slot, PorousBody<T>{});
  }
  if (mode == UpdateMode::full) {
    std::fill(field_.d.begin(), field_.d.end(), 1.0f);
    std::fill(field_.body.begin(), field_.body.end(), -1);
    for (Tracked& t : tracked_) t.band.clear();
  }

  std::vector<std::int32_t> order;
  order.reserve(by_id.size());
  for (std::size_t i : by_id) {
    const BodyState& s = states[i];
    std::int32_t slot = slot_of(s.id);
    const bool fresh = slot < 0;
    if (fresh) {
      const auto free =
          std::find_if(tracked_.begin(), tracked_.end(), [](const Tracked& t) { return t.id < 0; });
      slot = static_cast<std::int32_t>(free - tracked_.begin());
      if (free == tracked_.end()) {
        tracked_.emplace_back();
        field_.bodies.push_back(PorousBody<T>{});
      }
      slots_[s.id] = slot;
    }
    order.push_back(slot);
    Tracked& t = tracked_[static_cast<std::size_t>(slot)];
    Tracked next;
    next.id = s.id;
    next.shape = s.shape;
    set_pose(next, s);

    std::vector<BandCell> band;
    band.reserve(t.band.size() + t.band.size() / 8 + 16);  // the band changes little per step
    if (fresh || mode == UpdateMode::full) {
      t = std::move(next);
      scan(slot, band, stats);
    } else if (t.shape != s.shape || displacement(t, next) > kMaxIncrementalMove) {
      remove(slot, stats);
      t = std::move(next);
      scan(slot, band, stats);
    } else {
      next.band = std::move(t.band);
      t = std::move(next);
      follow_band(slot, band, stats);
    }
    t.band = std::move(band);
    stats.band += t.band.size();
    reset_touched();

    // The centre is wrapped again in T: t.x < L may round up to L.
    PorousBody<T> k;
    for (int a = 0; a < 3; ++a) {
      const T c = T(t.x[a]);
      k.centre[a] = sub_.periodic[a] ? wrap_periodic(c, T(sub_.box.global[a])) : c;
      k.velocity[a] = T(s.v[a] / frame_.units.velocity());
      k.omega[a] = T(s.w[a] * frame_.units.dt);
    }
    field_.bodies.set(static_cast<std::size_t>(slot), k);
  }
  combine(order);
  field_.active = !slots_.empty();
  return stats;
}

template class BodyField<double>;
template class BodyField<float>;

}  // namespace lbdem::hlbm
