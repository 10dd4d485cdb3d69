#pragma once
// The smoothed reference porosity of one shape (paper, appendix "Representation of a
// particle in the fluid"): the shape's reference lattice gives each voxel's porosity, its fluid
// volume fraction 1 - fill (the paper uses 0/1 voxels; fractions make the embedded volume match
// the body's, docs/method.md "Reference lattice"); a fluid node mapped into the shape frame gets
// the average of that porosity over the mapped point and its q - 1 = 18 D3Q19 neighbours at the
// stencil spacing h = dx / 2, `step` voxels per offset c_i (the scenes' lattice has voxels
// of h / 2, each holding the solid fraction of a box of side h about it, so that no stencil
// point moves by more than h / 4 to the voxel it reads: docs/method.md, "Reference lattice").
//
// Two lookups (scene key fluid.porosity_lookup, docs/performance.md compares them):
// * trilinear interpolation of the reference lattice: the porosity of a node, and with it the
//   penalization and the set of boundary links, changes continuously when the body moves or
//   turns by a fraction of a voxel. Because the 19-point average and trilinear
//   interpolation are both linear and the stencil offsets are whole voxels (step of them), the two
//   commute exactly: we average once on the reference lattice at construction and a lookup
//   is one trilinear interpolation (8 loads) instead of 19 of them.
// * nearest voxel (the paper's construction): each of the 19 D3Q19 stencil points x + h c_i
//   of the node, taken in the lattice frame and mapped into the shape frame, reads the voxel
//   nearest to it (19 loads). In the lattice frame the stencil point of a node towards a
//   neighbour is the neighbour's stencil point towards the node (spacing h = dx / 2), so a
//   node with d = 0 never neighbours a node with d = 1 and the band holds every boundary
//   link, at any orientation. d changes by jumps as the body moves, and the band
//   (0 < d < 1) is narrower than the trilinear one.
#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/choices.hpp"

namespace lbdem::hlbm {

// The nearest lookup's rounding, floor(x + kNearestHalf) in voxel coordinates: round half up,
// with ties judged within kTieTolerance voxels. A point on a voxel face is a tie, and a body
// whose centre sits on a multiple of h/2 with identity orientation (any quarter turn) puts
// every stencil point of every node on a face when the voxel count is even (voxel faces then
// lie on multiples of h from the centre, the stencil points too). Exact rounding would send
// them all up, but the map into the reference lattice (ref = R^T r dx/h + shift, shift read
// from the lattice origin) carries a round-off of a few 1e-15 voxels of one sign, and whether a
// sum x + 0.5 then lands just below the integer or on it depends on x's magnitude: the points
// below the centre fell to the lower voxel and those above it to the upper, both outward, and
// the fluid saw the sphere 0.25 cells smaller in radius (K -16 % for phi 0.343 at 28 cells,
// docs/validation.md section 7). The tolerance, far above the round-off of any coordinate of a
// lattice of fewer than 1e6 voxels across and far below any length that matters, sends every
// tie up, so a tie pose reads like a pose 1e-9 voxels away.
inline constexpr double kTieTolerance = 1e-9;
inline constexpr double kNearestHalf = 0.5 + kTieTolerance;

// The nearest lookup's 19 stencil offsets s R^T c_i (reference-lattice units, s the stencil's
// step in voxels) as it reads them: one array per axis, padded to 20 with a zero offset, so the
// mapping of all points vectorizes.
struct NearestStencil {
  static constexpr int kPoints = 19, kPadded = 20;
  alignas(32) std::array<double, kPadded> x{}, y{}, z{};
  // Per axis, the largest |offset| plus 1e-9 voxels (far above the round-off of a mapped point;
  // at most s sqrt 2 + 1e-9 since |R^T c_i| <= sqrt 2): what the batched lookup's boxes rest on.
  std::array<double, 3> extent{0, 0, 0};
  void set_extent();
};

// Nodes for a batched lookup: `count` nodes with their reference-lattice coordinates, one array
// per axis (the caller fills them), their porosity, and the `mixed_count` nodes whose porosity
// may lie strictly between 0 and 1 (ReferencePorosity::nearest: those whose box is mixed), in
// batch order. The arrays only grow, so that refilling a batch clears no memory.
struct NearestBatch {
  std::size_t count = 0, mixed_count = 0;
  std::vector<double> x, y, z;
  std::vector<float> d;
  std::vector<std::uint32_t> mixed;  // 4 entries more, for branch-free appends
  // Room for n nodes; keeps the first `count`.
  void resize(std::size_t n) {
    if (x.size() < n) {
      const std::size_t c = std::max(n, 2 * x.size());
      for (auto* v : {&x, &y, &z}) v->resize(c);
      d.resize(c);
      mixed.resize(c + 4);
    }
    count = n;
  }
  std::span<const std::uint32_t> mixed_nodes() const { return {mixed.data(), mixed_count}; }
};

class ReferencePorosity {
 public:
  // step: the stencil spacing h = dx / 2 in voxels (1 or more; BodyField takes it from dx).
  ReferencePorosity(const Voxels& voxels, int step);

  // Porosity at a point given in reference-lattice coordinates (see to_reference): 1 off the
  // lattice, 0 deep inside. Exactly 0 or 1 where all 8 interpolation corners are.
  double at(const Eigen::Vector3d& ref) const;
  // The paper's lookup: the fraction of the 19 points ref + stencil[i] whose nearest voxel is
  // fluid; stencil[i] is the lattice-frame offset h c_i in reference-lattice coordinates
  // (step R^T c_i). Exactly 0 or 1 when all 19 agree.
  double nearest(const Eigen::Vector3d& ref, const NearestStencil& stencil) const;
  // The same for every node of a batch (sets batch.d), bit for bit what the single-node lookup
  // gives: the nodes whose box is mixed read their points several nodes at a time.
  void nearest(NearestBatch& batch, const NearestStencil& stencil) const;

  // Reference-lattice coordinates of a shape-frame point p (m): ref = p / h + shift().
  double spacing() const { return h_; }
  int step() const { return step_; }
  const Eigen::Vector3d& shift() const { return shift_; }

  // Largest distance of a point with porosity < 1 from the shape-frame origin (m).
  double support_radius() const { return support_radius_; }
  // Largest distance of a corner of a voxel holding solid from the shape-frame origin (m).
  double surface_radius() const { return surface_radius_; }

 private:
  // Whether a box of voxels is all fluid, all solid, or mixed.
  enum class Block : std::uint8_t { mixed, fluid, solid };
  double h_ = 0;
  int step_ = 1;
  // Padding layers of fluid voxels: step for the 19-point stencil and one for trilinear.
  int pad_ = 2;
  Eigen::Vector3d shift_ = Eigen::Vector3d::Zero();
  std::array<int, 3> m_{0, 0, 0};  // padded extents
  std::vector<float> smooth_;      // averaged porosity, padded lattice, x fastest
  // Fluid fraction of each voxel (1 - fill) on the padded lattice grown by point_pad_ =
  // ceil(step sqrt 2) more fluid layers: every stencil point of a node whose nearest voxel is on
  // the padded lattice reads it without a range check (components of step R^T c_i are at most
  // step sqrt 2). fluid_origin_ is the index of padded voxel (0, 0, 0), stride_ the steps in y, z.
  int point_pad_ = 2;
  std::vector<float> fluid_;
  std::ptrdiff_t fluid_origin_ = 0;
  std::array<std::ptrdiff_t, 2> stride_{0, 0};
  // Per voxel l (-point_pad_ <= l_a < m_a, stored at l + point_pad_): the class of the box_^3
  // voxels l .. l + box_ - 1 (beyond the padded lattice: fluid), box_ = ceil(2 step sqrt 2) + 1
  // (4 at step 1, 7 at step 2). A node at x = ref + kNearestHalf reads, per axis, voxels between
  // floor(x - e) and floor(x + e) (e: the stencil's extent), at most box_ of them since
  // 2 e <= box_ - 1.
  int box_ = 4;
  std::vector<Block> blocks_;
  std::array<std::size_t, 2> block_stride_{0, 0};
  double support_radius_ = 0;
  double surface_radius_ = 0;

  // Class of the box a node's points can reach, the node at x, y, z (reference coordinates,
  // kNearestHalf added); a node off the padded lattice is fluid (its points reach at most its
  // point_pad_ fluid layers).
  Block box_at(double x, double y, double z, const NearestStencil& stencil) const {
    if (!(x >= 0 && y >= 0 && z >= 0 && x < m_[0] && y < m_[1] && z < m_[2])) return Block::fluid;
    // On the padded lattice the box origins are >= -point_pad_.
    const auto i = static_cast<std::size_t>(std::floor(x - stencil.extent[0]) + point_pad_);
    const auto j = static_cast<std::size_t>(std::floor(y - stencil.extent[1]) + point_pad_);
    const auto l = static_cast<std::size_t>(std::floor(z - stencil.extent[2]) + point_pad_);
    return blocks_[i + block_stride_[0] * j + block_stride_[1] * l];
  }
  // The nearest lookup's 19 loads for a node of a mixed box, out of line so that the
  // shortcut inlines into the update loops.
  float read_points(double x, double y, double z, const NearestStencil& stencil) const;
  // The same for the nodes batch.mixed of a batch, several at a time where AVX2 is there.
  void read_points(NearestBatch& batch, const NearestStencil& stencil) const;

  float value(int i, int j, int k) const {
    return smooth_[static_cast<std::size_t>(i) +
                   static_cast<std::size_t>(m_[0]) *
                       (static_cast<std::size_t>(j) + static_cast<std::size_t>(m_[1]) * k)];
  }
};

// The lookups are inline: they are the inner loop of every porosity update.
namespace detail {
inline double lerp(double a, double b, double t) {
  return a + t * (b - a);
}
}  // namespace detail

inline double ReferencePorosity::at(const Eigen::Vector3d& ref) const {
  const double x = ref.x(), y = ref.y(), z = ref.z();
  // Outside the padded lattice everything is fluid; the outer layer of the padded lattice
  // is 1 as well, so the field is continuous across its edge. Inside, x >= 0 and the integer
  // conversion is the floor.
  if (!(x >= 0 && y >= 0 && z >= 0 && x < m_[0] - 1 && y < m_[1] - 1 && z < m_[2] - 1)) return 1.0;
  const int i = static_cast<int>(x), j = static_cast<int>(y), k = static_cast<int>(z);
  const double tx = x - i, ty = y - j, tz = z - k;
  const std::size_t sy = static_cast<std::size_t>(m_[0]);
  const std::size_t sz = sy * static_cast<std::size_t>(m_[1]);
  const float* p = &smooth_[static_cast<std::size_t>(i) + sy * j + sz * k];
  // Nested lerps (not a weighted sum): equal corners give exactly that value.
  const double c00 = detail::lerp(p[0], p[1], tx);
  const double c10 = detail::lerp(p[sy], p[sy + 1], tx);
  const double c01 = detail::lerp(p[sz], p[sz + 1], tx);
  const double c11 = detail::lerp(p[sz + sy], p[sz + sy + 1], tx);
  return detail::lerp(detail::lerp(c00, c10, ty), detail::lerp(c01, c11, ty), tz);
}

// A node's 19 points read voxels within its box (blocks_): where that box is uniform they all
// read the same value and the sum below is exactly 0 or 19. Cells beyond the band (most of the
// update's candidates) cost one load instead of 19; the result is the 19-point sum's bit for bit.
inline double ReferencePorosity::nearest(const Eigen::Vector3d& ref,
                                         const NearestStencil& stencil) const {
  switch (box_at(ref.x() + kNearestHalf, ref.y() + kNearestHalf, ref.z() + kNearestHalf, stencil)) {
    case Block::fluid:
      return 1.0;
    case Block::solid:
      return 0.0;
    case Block::mixed:
      break;
  }
  return read_points(ref.x(), ref.y(), ref.z(), stencil);
}

}  // namespace lbdem::hlbm
