#pragma once
// Imposing a given force F and torque T on each rigid body exactly, through LAMMPS's
// `fix external pf/callback` and the per-atom torque array.
//
// The force is spread over the body's clump spheres with weights w_i that satisfy
// sum w_i = 1 and sum w_i (x_i - x_cm) = 0: the net force is F and the spread adds no torque,
// even when the centre of mass (from the voxelization) differs from the spheres' centroid.
// Among such weights we take the least-squares ones. The weights are invariant under the
// body's motion (the constraints are linear in the body-frame offsets), so they are computed
// once. The torque is added as T / N to each sphere's torque; the rigid fix sums them.
#include <Eigen/Dense>

#include <array>
#include <cstdint>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"

namespace lbdem {

// Least-norm weights for a clump; throws std::invalid_argument when no weights can cancel
// the moment (e.g. a single sphere away from the centre of mass).
std::vector<double> force_weights(const Clump& clump);

// Per-body loads and the per-atom tables the callback needs. Atom tags are 1..N, body after
// body, in the order of the clump spheres (how the engine writes the data file).
class ExternalLoads {
 public:
  ExternalLoads() = default;
  // body_shape[b]: shape index of body b.
  ExternalLoads(const std::vector<Shape>& shapes, const std::vector<int>& body_shape);

  void set_load(std::int64_t body, const Eigen::Vector3d& force, const Eigen::Vector3d& torque);
  void set_extra_force(std::int64_t body, const Eigen::Vector3d& force);
  Eigen::Vector3d force(std::int64_t body) const;   // load + extra
  Eigen::Vector3d torque(std::int64_t body) const;  // load only
  bool active() const { return active_; }

  // Fills fext for the local atoms and adds the torque share to `torque` (LAMMPS arrays).
  template <class Tag>
  void apply(int nlocal, const Tag* tags, double** fext, double** torque) const;

  std::size_t bodies() const { return load_force_.size() / 3; }
  std::vector<double>& load_force() { return load_force_; }
  std::vector<double>& load_torque() { return load_torque_; }
  void refresh_active();

 private:
  std::vector<std::int64_t> atom_body_;                         // by tag - 1
  std::vector<double> atom_weight_;                             // by tag - 1
  std::vector<double> inv_count_;                               // 1 / spheres per body
  std::vector<double> load_force_, load_torque_, extra_force_;  // 3 per body
  bool active_ = false;
};

template <class Tag>
void ExternalLoads::apply(int nlocal, const Tag* tags, double** fext, double** torque) const {
  for (int i = 0; i < nlocal; ++i) {
    const auto a = static_cast<std::size_t>(tags[i] - 1);
    const auto b = static_cast<std::size_t>(atom_body_[a]);
    const double w = atom_weight_[a];
    for (int d = 0; d < 3; ++d) {
      fext[i][d] = w * (load_force_[3 * b + d] + extra_force_[3 * b + d]);
      torque[i][d] += inv_count_[b] * load_torque_[3 * b + d];
    }
  }
}

}  // namespace lbdem
