#pragma once
// The smoothed reference porosity of one shape (paper, appendix "Representation of a
// particle in the fluid"): the shape's voxelization at the reference spacing h (half the
// fluid spacing) gives a 0/1 porosity; a fluid node mapped into the shape frame gets the
// average of that porosity over the mapped point and its q - 1 = 18 D3Q19 neighbours at
// spacing h.
//
// Lookup: trilinear interpolation of the reference lattice (not nearest voxel), so that the
// porosity of a node, and with it the penalization and the set of boundary links, changes
// continuously when the body moves or turns by a fraction of a reference cell; nearest
// lookup would make d jump by 1/19 steps as the mapped point crosses a voxel boundary and
// feed that noise into the momentum exchange. Because the 19-point average and trilinear
// interpolation are both linear and the stencil offsets are whole reference cells, the two
// commute exactly: we average once on the reference lattice at construction and a lookup is
// one trilinear interpolation (8 loads) instead of 19 of them.
#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"

namespace lbdem::hlbm {

class ReferencePorosity {
 public:
  explicit ReferencePorosity(const Voxels& voxels);

  // Porosity at a point given in reference-lattice coordinates (see to_reference): 1 off the
  // lattice, 0 deep inside. Exactly 0 or 1 where all 8 interpolation corners are.
  double at(const Eigen::Vector3d& ref) const;

  // Reference-lattice coordinates of a shape-frame point p (m): ref = p / h + shift().
  double spacing() const { return h_; }
  const Eigen::Vector3d& shift() const { return shift_; }

  // Largest distance of a point with porosity < 1 from the shape-frame origin (m).
  double support_radius() const { return support_radius_; }
  // Largest distance of a solid voxel corner from the shape-frame origin (m).
  double surface_radius() const { return surface_radius_; }

 private:
  static constexpr int kPad = 2;  // one layer for the 19-point stencil, one for trilinear
  double h_ = 0;
  Eigen::Vector3d shift_ = Eigen::Vector3d::Zero();
  std::array<int, 3> m_{0, 0, 0};  // padded extents
  std::vector<float> smooth_;      // averaged porosity, padded lattice, x fastest
  double support_radius_ = 0;
  double surface_radius_ = 0;

  float value(int i, int j, int k) const {
    return smooth_[static_cast<std::size_t>(i) +
                   static_cast<std::size_t>(m_[0]) *
                       (static_cast<std::size_t>(j) + static_cast<std::size_t>(m_[1]) * k)];
  }
};

}  // namespace lbdem::hlbm
