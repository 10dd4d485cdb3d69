#include "dem_app/coupling/coupled_dem.hpp"

#include <chrono>
#include <filesystem>
#include <memory>

#include "coupler_lib/app/progress.hpp"
#include "coupler_lib/coupling/dem_coupler.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/coupling/stop_request.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/scene_fingerprint.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/body_output.hpp"
#include "dem_app/coupling/body_trace.hpp"
#include "dem_app/coupling/body_watch.hpp"
#include "dem_app/coupling/dem_checkpoint.hpp"
#include "dem_app/dem_run.hpp"
#include "dem_app/dem_setup.hpp"
#include "dem_app/lammps_engine.hpp"

namespace lbdem {

namespace {

// The DEM box must be periodic exactly where the fluid box is, or a body would leave one
// side and not the other.
void check_periodicity(const Scene& scene) {
  for (int a = 0; a < 3; ++a) {
    if (scene.dem->periodic[a] != scene.fluid->periodic(a))
      throw SceneError(scene.file + ": dem.periodic and fluid.boundaries disagree along " +
                       axis_name(a) + ": both sides must be periodic on the same axes");
  }
}

}  // namespace

int run_coupled_dem(AppContext& ctx) {
  const Scene& scene = ctx.scene;
  const bool replay = !ctx.cli.replay.empty();
  World world;
  if (!replay) world = connect(ctx);
  check_periodicity(scene);

  DemSetup setup = make_dem_setup(scene, build_scene_shapes(scene), true);
  std::filesystem::path dir(setup.params.output.directory);
  if (dir.is_relative()) dir = std::filesystem::path(scene.file).parent_path() / dir;
  if (ctx.rank == 0) std::filesystem::create_directories(dir);
  setup.lammps_log = (dir / (scene.name + "_lammps.log")).string();
  validate_dem_setup(setup);
  const Schedule schedule = make_schedule(scene, scene.fluid->units.dt, dem_time_step(setup));
  setup.params.dt = schedule.dt_dem;  // an integer number of substeps per fluid step
  if (ctx.rank == 0) {
    ctx.log->info("DEM: {}", describe_engine_inputs(setup));
    ctx.log->info("coupling: {} fluid steps of {:.4e} s, {} DEM substeps of {:.4e} s each",
                  schedule.steps, schedule.dt, schedule.dem_substeps, schedule.dt_dem);
  }
  LammpsEngine engine(ctx.side_comm, setup);

  // Weight is applied by LAMMPS (dem.gravity on the body mass); the fluid has no hydrostatic
  // pressure gradient, so the buoyancy of the displaced fluid is added here explicitly. In a
  // triply periodic box the compensating force acts on every lattice node, the bodies' too,
  // and reaches each body through the penalization load: nothing more is added here
  // (coupler_lib/scene/settling_balance.hpp).
  const double rho_f = scene.fluid->density;
  const Eigen::Vector3d g(scene.dem->gravity[0], scene.dem->gravity[1], scene.dem->gravity[2]);
  for (std::size_t id = 0; id < setup.bodies.size(); ++id) {
    const double volume = setup.shapes[size_t(setup.bodies[id].shape)].mass.volume;
    engine.set_extra_force(std::int64_t(id), -rho_f * volume * g);
  }

  // Checkpoints need both programs at the same step; with overlap they are one step apart
  // (the scene refuses checkpoint_interval there, and stop signals keep their default).
  const bool checkpoints = !replay && !scene.coupling.overlap;
  std::string journal;
  if (checkpoints) {
    install_stop_handlers();
    if (ctx.rank == 0) std::filesystem::create_directories(checkpoint_directory(scene));
    journal =
        (std::filesystem::path(checkpoint_directory(scene)) / (scene.name + "_dem_journal.h5"))
            .string();
  }
  std::unique_ptr<DemCoupler> coupler = replay
                                            ? std::make_unique<DemCoupler>(ctx, ctx.cli.replay)
                                            : std::make_unique<DemCoupler>(world, scene, journal);
  const int fluid_ranks = replay ? 0 : world.peer().size;

  // A restart: the checkpoint's step, its trace length, and the replay of its journal.
  std::int64_t first = 0;
  long long trace_bytes = -1;
  std::unique_ptr<DemCoupler> history;
  if (!ctx.cli.restart.empty()) {
    std::string prefix;
    DemRestart r;
    try {
      prefix = restart_prefix(ctx.cli.restart);
      r = read_dem_checkpoint(prefix,
                              make_checkpoint_header(scene, "dem", 0, 0, fluid_ranks, ctx.size));
    } catch (const std::runtime_error& e) {
      throw SideError(e.what());
    }
    first = r.header.step;
    trace_bytes = r.trace_bytes;
    remember_checkpoint(prefix);
    SideInfo journal_ctx = ctx;  // the journal is identified by the scene fingerprint
    journal_ctx.scene_hash = scene_fingerprint(scene);
    history = std::make_unique<DemCoupler>(journal_ctx, r.path);
    if (ctx.rank == 0)
      ctx.log->info("restart from {} at step {} (t = {:.6e} s): replaying the DEM's {} steps",
                    prefix, first, r.header.time, first);
  }

  std::unique_ptr<BodySnapshotWriter> snapshots;
  std::unique_ptr<BodyTrace> trace;
  if (schedule.output_interval > 0) {
    snapshots = std::make_unique<BodySnapshotWriter>(dir.string(), scene.name, ctx.side_comm);
    trace = std::make_unique<BodyTrace>((dir / (scene.name + "_bodies.csv")).string(),
                                        ctx.side_comm, history ? trace_bytes : -1);
  }

  Progress progress(ctx.log, scene.time.progress_interval, scene.time.end);
  std::vector<BodyState> owned = engine.owned_states(0);
  double dem_s = 0;  // wall time in LAMMPS, for the per-step split reported at the end
  auto advance = [&](std::int64_t step, const std::vector<BodyLoad>& loads) {
    for (const BodyLoad& l : loads)
      engine.set_load(l.id, Eigen::Vector3d(l.f[0], l.f[1], l.f[2]),
                      Eigen::Vector3d(l.t[0], l.t[1], l.t[2]));
    const auto t = std::chrono::steady_clock::now();
    engine.run(schedule.dem_substeps);
    dem_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    owned = engine.owned_states(step);
  };
  if (history) {
    // Steps 0..first again, fed by the journal, each state checked against it bit for bit.
    history->send_states(0, owned);
    coupler->journal_states(0, owned);
    const auto replay_start = std::chrono::steady_clock::now();
    for (std::int64_t step = 1; step <= first; ++step) {
      const std::vector<BodyLoad> loads = history->receive_loads(step);
      coupler->journal_loads(step, loads);
      advance(step, loads);
      history->send_states(step, owned);
      coupler->journal_states(step, owned);
    }
    history.reset();
    if (ctx.rank == 0)
      ctx.log->info(
          "replayed the DEM's {} steps bit for bit in {:.3f} s", first,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - replay_start).count());
  } else if (trace) {
    trace->write(0.0, owned, {});
    snapshots->write(owned, 0.0);
  }
  coupler->send_states(first, owned);
  std::string checkpoint;  // the last one written
  bool stopped = false;
  int unstable = 0;  // kFluidUnstable | kBodiesUnstable as both programs agreed
  const BodyWatchLimits limits = body_watch_limits(scene);
  std::string trouble;  // the bodies' diagnosis, once found
  for (std::int64_t step = first + 1; step <= schedule.steps; ++step) {
    const std::vector<BodyLoad> loads = coupler->receive_loads(step);
    advance(step, loads);
    const double time = double(step) * schedule.dt;
    if (schedule.output_at(step) && trace) {
      trace->write(time, owned, loads);
      snapshots->write(owned, time);
    }
    coupler->send_states(step, owned);
    progress.update(step, time);
    if (!checkpoints) continue;
    // Found at any step, reported at the next step both programs agree (the first finding
    // stays).
    const bool agree = agreement_at(scene, schedule, step);
    if (trouble.empty())
      trouble = check_bodies(owned, step, time, setup, limits, agree, ctx.side_comm);
    if (!agree) continue;
    const int flags = agree_flags(
        (stop_signal() != 0 ? kStopRequested : 0) | (trouble.empty() ? 0 : kBodiesUnstable), world,
        step);
    unstable = flags & (kFluidUnstable | kBodiesUnstable);
    if (unstable) {
      // Both programs stop here; the one that found the problem prints the diagnosis.
      if (ctx.rank == 0) {
        if (!trouble.empty())
          ctx.log->error("{}", trouble);
        else
          ctx.log->error(
              "stopped at step {}: fluid_app found the fluid unstable (its diagnosis "
              "above)",
              step);
        const std::string& last = remembered_checkpoint();
        ctx.log->error("last good checkpoint: {}",
                       last.empty() ? std::string("none (set coupling.checkpoint_interval)")
                                    : last + "; continue after changing the scene with: " +
                                          restart_command(scene, last, fluid_ranks, ctx.size));
      }
      break;
    }
    stopped = (flags & kStopRequested) != 0;
    if (!stopped && !schedule.checkpoint_at(step)) continue;
    checkpoint = checkpoint_prefix(scene, step);
    write_dem_checkpoint(checkpoint, coupler->flush_journal(),
                         make_checkpoint_header(scene, "dem", step, time, fluid_ranks, ctx.size),
                         trace ? trace->flushed_bytes() : -1, ctx.side_comm);
    // Older checkpoints go only once both halves of this one exist.
    wait_for_both(world, step);
    remember_checkpoint(checkpoint);
    if (ctx.rank == 0) prune_checkpoints(scene, "dem", scene.coupling.checkpoint_keep);
    if (stopped) {
      if (ctx.rank == 0)
        ctx.log->info(
            "stopped on request at step {} (t = {:.6e} s); checkpoint: {}; continue with: {}", step,
            time, checkpoint, restart_command(scene, checkpoint, fluid_ranks, ctx.size));
      break;
    }
  }
  if (ctx.rank == 0) {
    if (!stopped && !unstable)
      ctx.log->info("coupled DEM run finished after {} fluid steps", schedule.steps);
    const CouplingTimes c = coupler->times();
    const double n = double(std::max<std::int64_t>(schedule.steps, 1));
    ctx.log->info(
        "time per coupled step (DEM rank 0): DEM {:.3e} s ({} substeps), exchange {:.3e} s, "
        "idle (waiting for fluid_app) {:.3e} s",
        dem_s / n, schedule.dem_substeps, c.exchange_s() / n, c.idle_s / n);
    if (trace) ctx.log->info("bodies: {} and {}", trace->path(), snapshots->xdmf_path());
    if (replay)
      ctx.log->info("replay of {}: the states of all {} steps match the recording bit for bit",
                    ctx.cli.replay, schedule.steps);
  }
  // The journal served the checkpoints (each holds its own copy up to its step).
  coupler.reset();
  if (ctx.rank == 0 && !journal.empty()) {
    std::error_code ec;
    std::filesystem::remove(journal, ec);
    if (std::filesystem::is_empty(checkpoint_directory(scene), ec))
      std::filesystem::remove(checkpoint_directory(scene), ec);
  }
  return unstable ? kExitUnstable : 0;
}

}  // namespace lbdem
