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

  // Call before every `run N pre no post no`. Velocity Verlet gives each substep's end force
  // two half-kicks (the end of that substep and the start of the next), and without a set-up
  // the run's first half-kick reuses the previous run's last force, so the body would get
  // dt_DEM / 2 (F_old - F_new) besides dt F_new. The first force evaluation of the run
  // therefore carries (F_new - F_old) / 2 extra, and the run delivers exactly dt F_new: the
  // momentum the fluid gave is the momentum the body gets (docs/method-loads.md). With a
  // single substep there is no such evaluation inside the run and the half-kick lag remains.
  void begin_run(long substeps);

  // Fills fext for the local atoms and adds the torque share to `torque` (LAMMPS arrays);
  // the first call after begin_run adds the pending correction.
  template <class Tag>
  void apply(int nlocal, const Tag* tags, double** fext, double** torque);

  std::size_t bodies() const { return load_force_.size() / 3; }
  std::vector<double>& load_force() { return load_force_; }
  std::vector<double>& load_torque() { return load_torque_; }
  void refresh_active();

 private:
  std::vector<std::int64_t> atom_body_;                         // by tag - 1
  std::vector<double> atom_weight_;                             // by tag - 1
  std::vector<double> inv_count_;                               // 1 / spheres per body
  std::vector<double> load_force_, load_torque_, extra_force_;  // 3 per body
  std::vector<double> last_force_, last_torque_;  // load of the previous run, 3 per body
  std::vector<double> kick_force_, kick_torque_;  // correction of the run's first evaluation
  bool kick_ = false;
  bool active_ = false;
};

template <class Tag>
void ExternalLoads::apply(int nlocal, const Tag* tags, double** fext, double** torque) {
  for (int i = 0; i < nlocal; ++i) {
    const auto a = static_cast<std::size_t>(tags[i] - 1);
    const auto b = static_cast<std::size_t>(atom_body_[a]);
    const double w = atom_weight_[a];
    for (int d = 0; d < 3; ++d) {
      const std::size_t k = 3 * b + static_cast<std::size_t>(d);
      const double f = load_force_[k] + extra_force_[k] + (kick_ ? kick_force_[k] : 0.0);
      const double t = load_torque_[k] + (kick_ ? kick_torque_[k] : 0.0);
      fext[i][d] = w * f;
      torque[i][d] += inv_count_[b] * t;
    }
  }
  kick_ = false;
}

}  // namespace lbdem
