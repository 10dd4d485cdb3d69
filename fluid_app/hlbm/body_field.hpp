#pragma once
// The fluid side of the bodies (homogenized LBM): turns the body states the coupler
// delivers into the porosity field and body table the HLBM collision reads, keeping the
// update cost proportional to the body surfaces. Conventions: docs/method.md, "Bodies in the
// fluid: homogenized LBM". The loads on the bodies are integrated elsewhere, from what this
// field and the kernel leave: fluid_app/hlbm/penalty_loads.hpp (the default) and
// fluid_app/hlbm/momentum_exchange.hpp.
//
// Use (one per fluid rank):
//   hlbm::BodyField<T> bodies(shapes, {solver.box(), periodic}, {origin, units},
//                             solver.porous());
//   each step: bodies.update(states);  solver.step();  (then the loads)
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

  // The slots of the last update (field().body / field().bodies index them): how many, and
  // the body id in each (-1: a free slot).
  std::size_t slots() const { return tracked_.size(); }
  std::int64_t id_of(std::int32_t slot) const {
    return tracked_[static_cast<std::size_t>(slot)].id;
  }
  const LatticeFrame& frame() const { return frame_; }
  // Centre of the body in a slot at the last update (lattice coordinates, wrapped into the
  // domain on periodic axes): the point its loads' moments are summed about.
  const Eigen::Vector3d& centre(std::int32_t slot) const {
    return tracked_[static_cast<std::size_t>(slot)].x;
  }

  // A cell of a body's porous band (0 < d_k < 1): d_k and local coordinates, 12 B (the index
  // follows from the coordinates by a multiply-add; the coordinates from an index would need
  // divisions).
  struct BandCell {
    float d;
    std::array<std::uint16_t, 3> l;  // local coordinates
    CellIndex cell(const LocalBox& box) const { return box.index(l[0], l[1], l[2]); }
  };
  // The band of the body in `slot` at the last update, in cell order.
  std::span<const BandCell> band(std::int32_t slot) const {
    return tracked_[static_cast<std::size_t>(slot)].band;
  }

 private:
  struct Tracked {
    std::int64_t id = -1;  // -1: free slot
    std::int32_t shape = 0;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();           // centre, lattice coordinates
    Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();     // shape frame -> space frame
    Eigen::Matrix3d to_ref = Eigen::Matrix3d::Identity();  // rot^T dx / h
    // Nearest lookup: the lattice-frame stencil h c_i in reference coordinates (rot^T c_i).
    NearestStencil stencil;
    std::vector<BandCell> band;  // cells with 0 < d < 1
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
    std::vector<float> d;                   // porosity of the evaluated band cells, by window cell
    std::array<std::vector<double>, 3> r2;  // squared offset from the centre per window index
  };
  std::vector<ReferencePorosity> shapes_;
  PorosityLookup lookup_ = PorosityLookup::trilinear;
  Subdomain sub_;
  LatticeFrame frame_;
  PorousField<T>& field_;
  std::vector<Tracked> tracked_;  // by slot
  std::unordered_map<std::int64_t, std::int32_t> slots_;
  std::vector<std::uint32_t> touched_;  // cells touched by the body being updated
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
  double reach(const Tracked& t) const;
  std::array<std::vector<int>, 3> support(const Tracked& t) const;
  void scan(std::int32_t slot, std::vector<BandCell>& band, UpdateStats& stats);
  void remove(std::int32_t slot, UpdateStats& stats);
  void follow_band(std::int32_t slot, std::vector<BandCell>& band, UpdateStats& stats);
  void reset_touched();
  void combine(std::span<const std::int32_t> order);
  double displacement(const Tracked& t, const Tracked& next) const;
};

extern template class BodyField<double>;
extern template class BodyField<float>;

}  // namespace lbdem::hlbm
