#include "fluid_app/run/fluid_summary.hpp"

#include <algorithm>
#include <filesystem>

#include "coupler_lib/coupling/run_summary.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/output/atomic_file.hpp"
#include "coupler_lib/scene/scene_fingerprint.hpp"

namespace lbdem {

void write_fluid_summary(const AppContext& ctx, const FluidRunFigures& f) {
  const double n = double(std::max<std::int64_t>(f.steps, 1));
  RankTable table = gather_per_rank(
      {"busy_s_per_step", "busy_cpu_s_per_step", "max_rss_mib", "cells", "steps_per_s"},
      {f.step_wall_s / n, f.step_cpu_s / n, max_rss_mib(), f.cells, f.steps_per_s}, ctx.side_comm);
  if (ctx.rank != 0) return;
  const FluidParams& p = *ctx.scene.fluid;
  RunSummary s;
  s.program = ctx.program;
  s.side = "fluid";
  s.scene_file = ctx.scene.file;
  s.version = LBDEM_VERSION;
  s.fingerprint = scene_fingerprint(ctx.scene);
  s.fluid_ranks = ctx.size;
  s.last_step = f.steps;
  s.schedule_steps = step_count(ctx.scene.time.end, p.units.dt);
  s.dt = p.units.dt;
  s.end = f.unstable ? "unstable" : "completed";
  s.exit_status = f.exit_status;
  s.wall_s = f.wall_s;
  s.per_step_s = {{"lattice", f.step_wall_s / n}};
  s.per_step_cpu_s = {{"lattice", f.step_cpu_s / n}};
  s.ranks = std::move(table);
  s.imbalance_of = "busy_s_per_step";
  const std::string path = run_summary_path(ctx.scene, "fluid");
  if (const auto dir = std::filesystem::path(path).parent_path(); !dir.empty())
    std::filesystem::create_directories(dir);
  write_file_atomically(path, run_summary_json(s));
  ctx.log->info("run summary: {}", path);
}

}  // namespace lbdem
