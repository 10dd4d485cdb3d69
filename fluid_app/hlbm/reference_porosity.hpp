#pragma once
// The smoothed reference porosity of one shape (paper, appendix "Representation of a
// particle in the fluid"): the shape's voxelization at the reference spacing h (half the
// fluid spacing) gives each voxel's porosity, its fluid volume fraction 1 - fill (the paper
// uses 0/1 voxels; fractions make the embedded volume match the body's, docs/method.md
// "Reference lattice"); a fluid node mapped into the shape frame gets the average of that
// porosity over the mapped point and its q - 1 = 18 D3Q19 neighbours at spacing h.
//
// Two lookups (scene key fluid.porosity_lookup, docs/performance.md compares them):
// * trilinear interpolation of the reference lattice: the porosity of a node, and with it the
//   penalization and the set of boundary links, changes continuously when the body moves or
//   turns by a fraction of a reference cell. Because the 19-point average and trilinear
//   interpolation are both linear and the stencil offsets are whole reference cells, the two
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

#include <array>
#include <cstddef>
#include <cstdint>
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

// The nearest lookup's 19 stencil offsets R^T c_i (reference-lattice units) as it reads them:
// one array per axis, padded to 20 with a zero offset, so the mapping of all points vectorizes.
struct NearestStencil {
  static constexpr int kPoints = 19, kPadded = 20;
  alignas(32) std::array<double, kPadded> x{}, y{}, z{};
};

class ReferencePorosity {
 public:
  explicit ReferencePorosity(const Voxels& voxels);

  // Porosity at a point given in reference-lattice coordinates (see to_reference): 1 off the
  // lattice, 0 deep inside. Exactly 0 or 1 where all 8 interpolation corners are.
  double at(const Eigen::Vector3d& ref) const;
  // The paper's lookup: the fraction of the 19 points ref + stencil[i] whose nearest voxel is
  // fluid; stencil[i] is the lattice-frame offset h c_i in reference-lattice coordinates
  // (R^T c_i). Exactly 0 or 1 when all 19 agree.
  double nearest(const Eigen::Vector3d& ref, const NearestStencil& stencil) const;

  // Reference-lattice coordinates of a shape-frame point p (m): ref = p / h + shift().
  double spacing() const { return h_; }
  const Eigen::Vector3d& shift() const { return shift_; }

  // Largest distance of a point with porosity < 1 from the shape-frame origin (m).
  double support_radius() const { return support_radius_; }
  // Largest distance of a corner of a voxel holding solid from the shape-frame origin (m).
  double surface_radius() const { return surface_radius_; }

 private:
  static constexpr int kPad = 2;  // one layer for the 19-point stencil, one for trilinear
  // Whether the voxels within Chebyshev distance 2 of a voxel are all fluid, all solid, or mixed.
  enum class Block : std::uint8_t { mixed, fluid, solid };
  double h_ = 0;
  Eigen::Vector3d shift_ = Eigen::Vector3d::Zero();
  std::array<int, 3> m_{0, 0, 0};  // padded extents
  std::vector<float> smooth_;      // averaged porosity, padded lattice, x fastest
  std::vector<float> fluid_;       // fluid fraction of each voxel (1 - fill), same lattice
  // Per voxel: are the voxels within Chebyshev distance 2 (outside the lattice: fluid) all
  // fluid or all solid? Every stencil point of a node lies within 2 of the node's nearest voxel.
  std::vector<Block> block_;
  double support_radius_ = 0;
  double surface_radius_ = 0;

  // The nearest lookup's 19 loads (the uniform-block shortcut aside), out of line so that the
  // shortcut inlines into the update loops.
  double read_points(const Eigen::Vector3d& ref, const NearestStencil& stencil) const;

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

// The stencil offsets have components |o_a| <= |c_i| = sqrt(2) < 2 voxels, so each point's
// nearest voxel lies within Chebyshev distance 2 of the node's own nearest voxel: where that
// block is uniform the 19 points all read the same value and the sum below is exactly 0 or 19.
// Cells beyond the band (most of the update's candidates) cost one load instead of 19; the
// result is the 19-point sum's bit for bit.
inline double ReferencePorosity::nearest(const Eigen::Vector3d& ref,
                                         const NearestStencil& stencil) const {
  const std::size_t sy = static_cast<std::size_t>(m_[0]);
  const std::size_t sz = sy * static_cast<std::size_t>(m_[1]);
  {
    const double x = ref.x() + kNearestHalf, y = ref.y() + kNearestHalf, z = ref.z() + kNearestHalf;
    // Outside the padded lattice every point falls outside it or in its two fluid layers.
    if (!(x >= 0 && y >= 0 && z >= 0 && x < m_[0] && y < m_[1] && z < m_[2])) return 1.0;
    const Block b = block_[static_cast<std::size_t>(x) + sy * static_cast<std::size_t>(y) +
                           sz * static_cast<std::size_t>(z)];
    if (b == Block::fluid) return 1.0;
    if (b == Block::solid) return 0.0;
  }
  return read_points(ref, stencil);
}

}  // namespace lbdem::hlbm
