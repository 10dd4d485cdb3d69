#pragma once
// The mean-velocity controller (fluid.mean_velocity_control, coupler_lib/scene/fluid_section.hpp)
// outside the solver: the solver steps the lattice with the uniform force it is given, and this
// controller gives it, every control.every steps, the force
//   F = F_scene + F_ff + gain e + integral_gain sum e,   e = target - u_mean,
// from the mean flow the solver measured in the step just taken (lattice units; the force
// holds in between). F_scene is fluid.body_force; F_ff a feed-forward, e.g. the settling
// balance's force of a triply periodic box (fluid_app/coupling/settling_force.hpp).
//
//   MeanFlowControl<T> control(solver, params);   // solver measures its mean flow from now on
//   solver.step(); control.after_step();          // every step
#include <array>

#include "coupler_lib/scene/fluid_section.hpp"
#include "fluid_app/solver/fluid_solver.hpp"

namespace lbdem {

template <class T>
class MeanFlowControl {
 public:
  // `fluid.control` must be enabled; the solver must outlive the controller.
  MeanFlowControl(FluidSolver<T>& solver, const FluidParams& fluid);

  // After every solver step: at a control step, the new force goes to the solver.
  void after_step();
  // The feed-forward F_ff, applied at once (not only from the next control step).
  void set_feed_forward(const std::array<double, 3>& force);
  const std::array<double, 3>& feed_forward() const { return feed_forward_; }

  // The integral of the error (sum e): what a checkpoint stores besides the solver's memory.
  const std::array<double, 3>& integral() const { return integral_; }
  void restore(const std::array<double, 3>& integral) { integral_ = integral; }

 private:
  FluidSolver<T>& solver_;
  MeanVelocityControl params_;
  std::array<double, 3> target_{};       // lattice units
  std::array<double, 3> scene_force_{};  // F_scene, lattice units
  std::array<double, 3> feed_forward_{};
  std::array<double, 3> integral_{};
};

extern template class MeanFlowControl<double>;
extern template class MeanFlowControl<float>;

}  // namespace lbdem
