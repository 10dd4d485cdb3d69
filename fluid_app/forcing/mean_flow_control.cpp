#include "fluid_app/forcing/mean_flow_control.hpp"

namespace lbdem {

template <class T>
MeanFlowControl<T>::MeanFlowControl(FluidSolver<T>& solver, const FluidParams& fluid)
    : solver_(solver), params_(fluid.control) {
  for (int k = 0; k < 3; ++k) {
    target_[k] = params_.target[k] / fluid.units.velocity();
    scene_force_[k] = fluid.body_force[k] / fluid.units.acceleration();
  }
  solver_.measure_mean_flow(true);
}

template <class T>
void MeanFlowControl<T>::after_step() {
  if (solver_.steps() % params_.every != 0) return;
  const MeanFlow mean = solver_.mean_flow();
  std::array<double, 3> force{};
  for (int k = 0; k < 3; ++k) {
    const double e = target_[k] - mean.velocity[k];
    integral_[k] += e;
    force[k] = scene_force_[k] + feed_forward_[k] + params_.gain * e +
               params_.integral_gain * integral_[k];
  }
  solver_.set_uniform_force(force);
}

template <class T>
void MeanFlowControl<T>::set_feed_forward(const std::array<double, 3>& force) {
  feed_forward_ = force;
  std::array<double, 3> now{};
  for (int k = 0; k < 3; ++k)
    now[k] = scene_force_[k] + force[k] + params_.integral_gain * integral_[k];
  solver_.set_uniform_force(now);
}

template class MeanFlowControl<double>;
template class MeanFlowControl<float>;

}  // namespace lbdem
