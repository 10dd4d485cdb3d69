#pragma once
// The run summary of a fluid-only run: the file a coupled run writes
// (coupler_lib/coupling/run_summary.hpp), for the fluid alone, so that scripts read both kinds
// of runs the same way (tools/coupled_bench.py).
#include <cstdint>

#include "coupler_lib/app/run_app.hpp"

namespace lbdem {

// This rank's figures of the run.
struct FluidRunFigures {
  double step_wall_s = 0, step_cpu_s = 0;  // in the steps (each with output and stability watch)
  std::int64_t steps = 0;
  double cells = 0;        // this rank's interior cells
  double steps_per_s = 0;  // after the first progress line (Progress), 0 with fewer than two
  double wall_s = 0;       // the whole run, set-up included
  int exit_status = 0;
  bool unstable = false;  // the stability watch stopped the run
};

// Collective over ctx.side_comm; rank 0 writes <fluid.output.directory>/<name>_fluid_summary.json
// with one timed part, `lattice`, and per rank busy_s_per_step, busy_cpu_s_per_step,
// max_rss_mib, cells and steps_per_s.
void write_fluid_summary(const AppContext& ctx, const FluidRunFigures& f);

}  // namespace lbdem
