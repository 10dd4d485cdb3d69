#pragma once
// The fluid side's run loop, one step at a time, so that a coupling loop (or the output
// writers) can sit between steps:
//
//   FluidRun<double> run(ctx);          // solver + unit log + progress line
//   while (!run.done()) {
//     ... update run.solver().porous() from body states ...
//     run.step();                        // one fluid step, observers, progress line
//     ... momentum exchange with run.solver().population(i, cell) ...
//   }
//
// run_fluid_scene() is the whole fluid-only program (`fluid_app scene.yaml`): it picks the
// precision from fluid.precision and runs until time.end.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "coupler_lib/app/progress.hpp"
#include "coupler_lib/app/run_app.hpp"
#include "coupler_lib/geometry/shape.hpp"
#include "fluid_app/forcing/mean_flow_control.hpp"
#include "fluid_app/parallel/rebalance.hpp"
#include "fluid_app/solver/fluid_solver.hpp"

namespace lbdem {

struct StepInfo {
  std::int64_t step = 0;  // steps done
  double time = 0;        // simulated time in s
};

template <class T>
class FluidRun {
 public:
  using Observer = std::function<void(const FluidSolver<T>&, const StepInfo&)>;

  // Collective. Logs the derived numbers, throws SceneError if the scene is out of range.
  // `shapes`: the scene's shape catalogue, for fluid.decomposition: balanced (the initial
  // bodies' work); empty for a scene without bodies. `restart`: the layout a restart chose
  // (parallel/rebalance.hpp), which replaces the initial bodies' work.
  explicit FluidRun(AppContext& ctx, const std::vector<Shape>& shapes = {},
                    const LayoutChoice* restart = nullptr);

  FluidSolver<T>& solver() { return *solver_; }
  // The mean-velocity controller, null unless fluid.mean_velocity_control is on.
  MeanFlowControl<T>* control() { return control_.get(); }
  const FluidParams& params() const { return params_; }
  std::int64_t total_steps() const { return total_steps_; }
  bool done() const { return solver_->steps() >= total_steps_; }
  // The slice weights the decomposition's cuts were placed by (empty: regular blocks).
  const SliceWeights& layout_weights() const { return layout_weights_; }
  StepInfo info() const;

  // Called after every step (and once with step 0 by start()), e.g. by output writers.
  void add_observer(Observer o) { observers_.push_back(std::move(o)); }
  void start();  // call once before the first step: observers see the initial state
  void step();   // the solver's step, the controller's update, the observers
  double steps_per_s_after_first_line() const { return progress_->steps_per_s_after_first_line(); }

 private:
  AppContext& ctx_;
  FluidParams params_;
  SliceWeights layout_weights_;
  std::unique_ptr<FluidSolver<T>> solver_;
  std::unique_ptr<MeanFlowControl<T>> control_;
  std::int64_t total_steps_ = 0;
  std::unique_ptr<Progress> progress_;
  std::vector<Observer> observers_;
};

extern template class FluidRun<double>;
extern template class FluidRun<float>;

// The fluid-only program: returns the exit code.
int run_fluid_scene(AppContext& ctx);

// Log lines with dx, dt, lattice viscosity, Mach and Reynolds numbers, forces, boundaries.
void log_fluid_setup(const AppContext& ctx, const FluidParams& p);

}  // namespace lbdem
