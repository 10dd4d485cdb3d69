#pragma once
// The fluid side of the bodies (homogenized LBM): turns the body states the coupler
// delivers into the porosity field and body table the HLBM collision reads, keeping the
// update cost proportional to the body surfaces, and integrates the hydrodynamic force and
// torque on each body: by default from the penalization (docs/method.md Eqs. (13)-(15),
// docs/method-loads.md), or by momentum exchange (Eqs. (9)-(10)). Conventions: docs/method.md,
// "Bodies in the fluid: homogenized LBM".
//
// Use (one per fluid rank):
//   hlbm::BodyField<T> bodies(shapes, {solver.box(), periodic}, {origin, units},
//                             solver.porous());
//   each step: bodies.update(states);  solver.step();
//              auto loads = bodies.momentum_exchange(
//                  [&](int i, CellIndex c) { return solver.population(i, c); }, step);
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/units.hpp"
#include "fluid_app/hlbm/momentum_exchange.hpp"
#include "fluid_app/hlbm/reference_porosity.hpp"
#include "fluid_app/hlbm/subdomain.hpp"
#include "fluid_app/porous_field.hpp"

namespace lbdem::hlbm {

// Where the lattice sits in space and how lattice units map to SI.
struct LatticeFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // SI position of the domain's lower corner
  UnitConverter units;
};

enum class UpdateMode {
  incremental,  // revisit only the porous band of each body (cost ~ surface)
  full,         // recompute every cell covered by any body from scratch (cost ~ volume)
};

// What one update did, for cost measurements and diagnostics.
struct UpdateStats {
  std::size_t evaluated = 0;           // porosity evaluations (mapped lookups)
  std::size_t band = 0;                // cells with 0 < d_k < 1, summed over bodies
  std::size_t full_scans = 0;          // support scans (body new, moved > 1/2 cell, or removed)
  std::size_t interior_conflicts = 0;  // cells inside two bodies (overlap deeper than the band)
};

template <class T>
class BodyField {
 public:
  // shapes: the scene's catalogue (BodyState::shape indexes it). field: the arrays the
  // kernel reads (FluidSolver::porous()); they are (re)sized to the box and owned by the
  // caller, who must not write them while this object lives.
  // lookup: how a mapped node reads the shape's reference porosity (fluid.porosity_lookup).
  BodyField(std::span<const Shape> shapes, const Subdomain& sub, const LatticeFrame& frame,
            PorousField<T>& field, PorosityLookup lookup = PorosityLookup::trilinear);

  // Embeds the bodies at their new poses. `states` holds every body that can touch this
  // rank's box, each once, any order; bodies absent from it are taken out of the field.
  // Sets field().active while any body is present.
  UpdateStats update(std::span<const BodyState> states, UpdateMode mode = UpdateMode::incremental);

  const PorousField<T>& field() const { return field_; }
  const Subdomain& subdomain() const { return sub_; }

  // Largest distance (m) from a body's centre at which shape `shape` can give a node d < 1.
  // The coupler must deliver a body to every rank whose stored box (interior cells plus
  // the ghost layer) comes within this distance of the body's centre (minimum image).
  double reach(std::int32_t shape) const {
    return shapes_.at(static_cast<std::size_t>(shape)).support_radius();
  }

  // Body index in field().body / field().bodies of a body id, -1 if not present.
  std::int32_t slot_of(std::int64_t id) const;
  // Porosity d_k of one body alone at a local cell (what the two-body rule combines).
  float body_porosity(std::int64_t id, CellIndex cell) const;

  // Partial hydrodynamic force and torque (SI; torque about the centre of mass) on every
  // body of the last update from the penalization itself (docs/method-loads.md):
  //   F_k = -P_k^n + (Q_k^n - Q_k^{n-1}),  T_k = -M_k^n + (L_k^n - L_k^{n-1}),
  // with the sums the kernel wrote in the last step (PorousField::exchange) over the cells
  // this rank owns. Call once per step, after the solver step: it keeps Q^n for the next.
  // Throws std::logic_error if a body left this rank while it still covered some of its
  // cells (its last Q could then not be returned; the coupler's reach prevents it).
  std::vector<BodyLoad> penalty_loads(std::int64_t step);

  // What penalty_loads keeps from one step to the next (Q^n, L^n of this rank's cells per
  // tracked body), for checkpoints; restore_covered sets it for a tracked body after a
  // restart's first update (throws std::out_of_range when the body is not tracked here).
  struct CoveredMemory {
    std::int64_t id = -1;
    std::array<double, 3> covered{}, covered_moment{};
  };
  std::vector<CoveredMemory> covered_memory() const;
  void restore_covered(const CoveredMemory& m);

  // The same loads by momentum exchange over the boundary links of the cells this rank owns
  // (the older method, fluid.loads: momentum_exchange; it misses the momentum of cells that
  // enter or leave a moving body's band and the body force inside it).
  // f(i, cell): post-stream population i at local cell `cell` (FluidSolver::population).
  template <class Populations>
  std::vector<BodyLoad> momentum_exchange(const Populations& f, std::int64_t step) const;

 private:
  struct BandCell {
    std::uint32_t cell;
    float d;
    std::array<std::uint16_t, 3> l;  // local coordinates (no index division to recover them)
  };
  struct Tracked {
    std::int64_t id = -1;  // -1: free slot
    std::int32_t shape = 0;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();           // centre, lattice coordinates
    Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();     // shape frame -> space frame
    Eigen::Matrix3d to_ref = Eigen::Matrix3d::Identity();  // rot^T dx / h
    // Nearest lookup: the lattice-frame stencil h c_i in reference coordinates (rot^T c_i).
    NearestStencil stencil;
    std::vector<BandCell> band;  // cells with 0 < d < 1
    // Q and L of the last step (this rank's cells), for the difference in penalty_loads.
    std::array<double, 3> covered{}, covered_moment{};
  };

  // The band search of one body runs on a window: the product of its support lists (local
  // coordinates per axis within reach, support()), window index w_a -> local lists[a][w_a].
  // Sets of window cells are bit rows (x along the bits, one row per (w_y, w_z)).
  struct Window {
    std::array<std::vector<int>, 3> l;    // local coordinate per window index
    std::array<std::vector<int>, 3> inv;  // window index per local coordinate, -1 outside
    int words = 0;                        // 64-bit words per row
    std::size_t rows = 0;
    // Per x word: bit w set when window x index w is the x neighbour of w - 1 (up) or of
    // w + 1 (down) in the box (the lists skip the cells out of reach).
    std::vector<std::uint64_t> adjacent_up, adjacent_down;
    // rows x words: evaluated, band found, old band, to dilate, to evaluate
    std::vector<std::uint64_t> evaluated, band, old, frontier, candidates;
    std::vector<std::uint8_t> in_frontier, in_candidates;  // per row: listed below
    std::vector<std::size_t> frontier_rows, candidate_rows;
    std::vector<std::uint64_t> grown, fresh;  // one row: dilated frontier, cells to evaluate
    std::vector<float> d;  // porosity of the evaluated band cells, by window cell
  };
  std::vector<ReferencePorosity> shapes_;
  PorosityLookup lookup_ = PorosityLookup::trilinear;
  Subdomain sub_;
  LatticeFrame frame_;
  PorousField<T>& field_;
  std::vector<Tracked> tracked_;  // by slot
  std::unordered_map<std::int64_t, std::int32_t> slots_;
  std::vector<std::uint32_t> touched_;  // cells evaluated in this update
  Window window_;                       // band search scratch
  // The cells of batch_: cell index and window row and x index (grown with batch_).
  struct Queue {
    std::vector<std::uint32_t> cell, row, i;
    void resize(std::size_t n) {
      if (cell.size() < n)
        for (auto* v : {&cell, &row, &i}) v->resize(std::max(n, 2 * v->size()));
    }
  };
  Queue queue_;
  NearestBatch batch_;  // the queued cells mapped into the reference lattice, and their porosity
  std::vector<std::int64_t> departed_;  // bodies taken out in the last update with Q != 0
  // Minimum-image offset from the centre of the body being updated, per axis and local
  // coordinate (lattice units): tabulated once per body and update, read per evaluation.
  std::array<std::vector<double>, 3> rel_;

  void set_pose(Tracked& t, const BodyState& s) const;
  float porosity(const Tracked& t, const Eigen::Vector3d& r) const;
  void tabulate_offsets(const Tracked& t);
  void queue_row(const Tracked& t, std::size_t row, const std::uint64_t* bits);
  void evaluate_queue(std::int32_t slot, UpdateStats& stats);
  void mark_interior(std::int32_t slot, std::uint32_t cell, float d, UpdateStats& stats);
  void open_window(const std::array<std::vector<int>, 3>& lists);
  std::array<std::vector<int>, 3> support(const Tracked& t) const;
  void scan(std::int32_t slot, std::vector<BandCell>& band, UpdateStats& stats);
  void remove(std::int32_t slot, UpdateStats& stats);
  void follow_band(std::int32_t slot, std::vector<BandCell>& band, UpdateStats& stats);
  void combine(std::span<const std::int32_t> order);
  double displacement(const Tracked& t, const Tracked& next) const;
};

template <class T>
template <class Populations>
std::vector<BodyLoad> BodyField<T>::momentum_exchange(const Populations& f,
                                                      std::int64_t step) const {
  std::vector<BodyLoad> loads;
  for (std::size_t s = 0; s < tracked_.size(); ++s) {
    const Tracked& t = tracked_[s];
    if (t.id < 0) continue;
    const auto slot = static_cast<std::int32_t>(s);
    // Interior cells (d = 0) never neighbour a cell outside the body (the smoothing is
    // wider than a link, docs/method.md "Momentum exchange"), so the body's band holds all its
    // boundary links.
    LinkLoad sum;
    for (const BandCell& b : t.band) {
      const auto l = sub_.box.coords(b.cell);
      if (field_.body[b.cell] == slot && sub_.box.interior(l[0], l[1], l[2]))
        sum += link_load(sub_, field_, slot, CellIndex(b.cell), f);
    }
    BodyLoad load;
    load.id = t.id;
    load.step = step;
    for (int a = 0; a < 3; ++a) {
      load.f[a] = sum.force[a] * frame_.units.force();
      load.t[a] = sum.torque[a] * frame_.units.torque();
    }
    loads.push_back(load);
  }
  return loads;
}

extern template class BodyField<double>;
extern template class BodyField<float>;

}  // namespace lbdem::hlbm
