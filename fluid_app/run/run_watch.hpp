#pragma once
// What fluid_app does around its steps besides stepping: the scene's output (fields, series),
// the stability watch and the validation (initial state, error at the end). It observes a
// FluidRun; the run loop asks stopped() after each step and returns finish()'s exit code:
//
//   FluidRun<T> run(ctx);
//   RunWatch<T> watch(ctx, run);
//   run.start();
//   while (!run.done() && !watch.stopped()) run.step();
//   return watch.finish();
//
// The macroscopic fields are computed only at steps where something is due.
#include <chrono>
#include <functional>
#include <memory>
#include <optional>

#include "coupler_lib/errors.hpp"
#include "fluid_app/output/fluid_output.hpp"
#include "fluid_app/output/macro_fields.hpp"
#include "fluid_app/run/fluid_run.hpp"
#include "fluid_app/stability/stability_watch.hpp"
#include "fluid_app/validation/reference_solution.hpp"

namespace lbdem {

// Density and physical velocity of the solver's interior cells, in double precision.
template <class T>
void fill_macro_fields(const FluidSolver<T>& solver, MacroFields& out);

template <class T>
class RunWatch {
 public:
  // Collective. Registers itself with `run` (must outlive it) and, for a validation case that
  // starts from its analytic solution, sets the initial state.
  // `series_resume_bytes` >= 0: a restart continues the series from that length.
  RunWatch(AppContext& ctx, FluidRun<T>& run, long long series_resume_bytes = -1);
  RunWatch(const RunWatch&) = delete;
  RunWatch& operator=(const RunWatch&) = delete;

  bool stopped() const { return failure_.has_value(); }
  // Also check the fluid at the steps `extra` names (a coupled run: every checkpoint step, so
  // that a checkpoint always holds a state that passed the check).
  void check_also_at(std::function<bool(long)> extra) { extra_ = std::move(extra); }
  // Bytes of the CSV series on disk (rank 0; -1 without), for checkpoints.
  long long series_bytes() { return output_ ? output_->series_bytes() : -1; }
  // Collective, after the loop: the validation report; the exit code. A run the stability
  // watch did not stop leaves no last good file (it is a diagnosis).
  int finish();

 private:
  void observe(const FluidSolver<T>& solver, const StepInfo& info);

  AppContext& ctx_;
  FluidRun<T>& run_;
  const FluidOutputParams& params_;
  std::unique_ptr<FluidOutput> output_;
  std::unique_ptr<StabilityWatch> stability_;
  std::optional<ReferenceSolution> reference_;
  std::optional<StabilityFailure> failure_;
  std::function<bool(long)> extra_;
  MacroFields fields_;
  std::chrono::steady_clock::time_point started_;
};

extern template class RunWatch<double>;
extern template class RunWatch<float>;

}  // namespace lbdem
