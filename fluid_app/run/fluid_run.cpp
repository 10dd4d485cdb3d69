#include "fluid_app/run/fluid_run.hpp"

#include "coupler_lib/coupling/coupling_times.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "fluid_app/parallel/balance.hpp"
#include "fluid_app/run/fluid_summary.hpp"
#include "fluid_app/run/run_watch.hpp"

#include <spdlog/fmt/fmt.h>

#include <chrono>
#include <cmath>

namespace lbdem {

void log_fluid_setup(const AppContext& ctx, const FluidParams& p) {
  const UnitConverter& u = p.units;
  ctx.log->info("fluid lattice {} x {} x {} = {} cells, precision {}", p.cells[0], p.cells[1],
                p.cells[2], double(p.cells[0]) * p.cells[1] * p.cells[2],
                word_of(kPrecisionWords, p.precision));
  std::string d = u.describe();
  for (std::size_t b = 0, e; b < d.size(); b = e + 1) {
    e = d.find('\n', b);
    if (e == std::string::npos) e = d.size();
    ctx.log->info("{}", d.substr(b, e - b));
  }
  std::string faces;
  for (int f = 0; f < 6; ++f) {
    faces += fmt::format("{}{}: {}", f ? ", " : "", face_name(f), face_type_name(p.faces[f].type));
    if (p.faces[f].type == FaceType::moving_wall)
      faces += fmt::format(" [{}, {}, {}] m/s", p.faces[f].velocity[0], p.faces[f].velocity[1],
                           p.faces[f].velocity[2]);
    if (p.faces[f].type == FaceType::pressure) faces += fmt::format(" {} Pa", p.faces[f].pressure);
  }
  ctx.log->info("boundaries: {}", faces);
  const double a = u.acceleration();
  if (p.body_force != std::array<double, 3>{})
    ctx.log->info("body force: [{}, {}, {}] m/s^2 = [{:.4g}, {:.4g}, {:.4g}] lattice",
                  p.body_force[0], p.body_force[1], p.body_force[2], p.body_force[0] / a,
                  p.body_force[1] / a, p.body_force[2] / a);
  if (p.control.enabled)
    ctx.log->info(
        "mean velocity control: target [{}, {}, {}] m/s, gain {}, integral gain {} (per update, "
        "every {} steps)",
        p.control.target[0], p.control.target[1], p.control.target[2], p.control.gain,
        p.control.integral_gain, p.control.every);
}

template <class T>
FluidRun<T>::FluidRun(AppContext& ctx, const std::vector<Shape>& shapes,
                      const LayoutChoice* restart)
    : ctx_(ctx), params_(*ctx.scene.fluid) {
  log_fluid_setup(ctx, params_);
  std::string layout = "regular";
  if (restart) {
    layout_weights_ = restart->weights;
    layout = restart->why;
  } else if (params_.decomposition == DecompositionKind::balanced && !ctx.scene.bodies.empty()) {
    layout_weights_ = body_work_weights(params_, ctx.scene.bodies, shapes);
    layout = "balanced by the initial bodies' work";
  }
  solver_ = std::make_unique<FluidSolver<T>>(params_, ctx.side_comm, std::array<int, 3>{0, 0, 0},
                                             layout_weights_);
  if (params_.control.enabled) control_ = std::make_unique<MeanFlowControl<T>>(*solver_, params_);
  const auto& d = solver_->decomposition();
  ctx.log->info("decomposition {} x {} x {} ranks ({}); kernel moves {} B per cell update",
                d.dims()[0], d.dims()[1], d.dims()[2], layout,
                FluidSolver<T>::bytes_per_cell_update(false));
  total_steps_ = step_count(ctx.scene.time.end, params_.units.dt);
  ctx.log->info("{} steps to t = {} s", total_steps_, ctx.scene.time.end);
  progress_ =
      std::make_unique<Progress>(ctx.log, ctx.scene.time.progress_interval, ctx.scene.time.end,
                                 double(params_.cells[0]) * params_.cells[1] * params_.cells[2]);
}

template <class T>
StepInfo FluidRun<T>::info() const {
  return {solver_->steps(), double(solver_->steps()) * params_.units.dt};
}

template <class T>
void FluidRun<T>::start() {
  const StepInfo i = info();
  for (auto& o : observers_) o(*solver_, i);
}

template <class T>
void FluidRun<T>::step() {
  solver_->step();
  if (control_) control_->after_step();
  const StepInfo i = info();
  for (auto& o : observers_) o(*solver_, i);
  progress_->update(i.step, i.time);
}

template class FluidRun<double>;
template class FluidRun<float>;

namespace {

template <class T>
int run_typed(AppContext& ctx) {
  const auto started = std::chrono::steady_clock::now();
  FluidRun<T> run(ctx);
  RunWatch<T> watch(ctx, run);  // output, stability watch, validation
  run.start();
  FluidRunFigures f;
  while (!run.done() && !watch.stopped()) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = thread_cpu_seconds();
    run.step();
    f.step_wall_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    f.step_cpu_s += thread_cpu_seconds() - cpu_start;
  }
  ctx.log->info("fluid run finished after {} steps", run.solver().steps());
  const int rc = watch.finish();
  // Like every other file of a fluid-only run, only when the scene asks for output (a scene
  // run in place must not leave files beside itself).
  if (run.params().output.writes_files()) {
    f.steps = run.solver().steps();
    f.cells = double(run.solver().box().interior_cells());
    f.steps_per_s = run.steps_per_s_after_first_line();
    f.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    f.exit_status = rc;
    f.unstable = watch.stopped();
    write_fluid_summary(ctx, f);
  }
  return rc;
}

}  // namespace

int run_fluid_scene(AppContext& ctx) {
  if (!ctx.scene.fluid) {
    ctx.log->error("the scene has no 'fluid' section: nothing for fluid_app to do");
    return 1;
  }
  return ctx.scene.fluid->precision == Precision::float32 ? run_typed<float>(ctx)
                                                          : run_typed<double>(ctx);
}

}  // namespace lbdem
