#include "dem_app/coupling/coupled_dem.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>

#include "coupler_lib/app/progress.hpp"
#include "coupler_lib/coupling/coupling_session.hpp"
#include "coupler_lib/coupling/dem_coupler.hpp"
#include "coupler_lib/coupling/journal.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/geometry/display_surface.hpp"
#include "coupler_lib/scene/scene_fingerprint.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/coupling/body_trace.hpp"
#include "dem_app/coupling/body_watch.hpp"
#include "dem_app/coupling/dem_checkpoint.hpp"
#include "dem_app/engine/lammps_engine.hpp"
#include "dem_app/output/body_output.hpp"
#include "dem_app/run/dem_run.hpp"
#include "dem_app/setup/dem_setup.hpp"

namespace lbdem {

int run_coupled_dem(AppContext& ctx) {
  const Scene& scene = ctx.scene;
  const bool replay = !ctx.cli.replay.empty();
  World world;
  if (!replay) world = connect(ctx);

  DemSetup setup = make_dem_setup(scene, build_scene_shapes(scene), true);
  std::filesystem::path dir(setup.params.output.directory);
  if (dir.is_relative()) dir = std::filesystem::path(scene.file).parent_path() / dir;
  if (ctx.rank == 0) std::filesystem::create_directories(dir);
  setup.lammps_log = (dir / (scene.name + "_lammps.log")).string();
  validate_dem_setup(setup);
  CouplingSession session(ctx, scene, coupled_schedule(scene, setup.shapes),
                          replay ? nullptr : &world);
  const Schedule& schedule = session.schedule();
  setup.params.dt = schedule.dt_dem;  // an integer number of substeps per fluid step
  if (ctx.rank == 0) {
    ctx.log->info("DEM: {}", describe_engine_inputs(setup));
    ctx.log->info("coupling: {} fluid steps of {:.4e} s, {} DEM substeps of {:.4e} s each",
                  schedule.steps, schedule.dt, schedule.dem_substeps, schedule.dt_dem);
  }
  LammpsEngine engine(ctx.side_comm, setup);

  // The DEM half of a checkpoint is the journal of every exchange up to its step.
  const std::string journal =
      session.agrees()
          ? (std::filesystem::path(checkpoint_directory(scene)) / (scene.name + "_dem_journal.h5"))
                .string()
          : std::string();
  std::unique_ptr<DemCoupler> coupler = replay
                                            ? std::make_unique<DemCoupler>(ctx, ctx.cli.replay)
                                            : std::make_unique<DemCoupler>(world, scene, journal);

  // A restart: the checkpoint's step, its trace length, and the replay of its journal.
  long long trace_bytes = -1;
  std::unique_ptr<DemCoupler> history;
  std::string restart_from;
  if (!ctx.cli.restart.empty()) {
    DemRestart r;
    try {
      restart_from = restart_prefix(ctx.cli.restart);
      r = read_dem_checkpoint(restart_from, session.header(0), ctx.rank);
    } catch (const std::runtime_error& e) {
      throw SideError(e.what());
    }
    session.resume(restart_from, r.header.step);
    trace_bytes = r.trace_bytes;
    SideInfo journal_ctx = ctx;  // the journal is identified by the scene fingerprint
    journal_ctx.scene_hash = scene_fingerprint(scene);
    try {
      history = DemCoupler::replaying_journal(journal_ctx, r.part);
    } catch (const std::runtime_error& e) {
      throw SideError(e.what());
    }
    if (ctx.rank == 0)
      ctx.log->info("restart from {} at step {} (t = {:.6e} s): replaying the DEM's {} steps",
                    restart_from, session.step(), r.header.time, session.step());
  }

  std::unique_ptr<BodySnapshotWriter> snapshots;
  std::unique_ptr<BodyTrace> trace;
  if (schedule.output_interval > 0) {
    snapshots = std::make_unique<BodySnapshotWriter>(
        dir.string(), scene.name, ctx.side_comm,
        setup.params.output.surfaces ? display_surfaces(scene.shapes, setup.shapes)
                                     : std::vector<TriangleMesh>{});
    trace = std::make_unique<BodyTrace>((dir / (scene.name + "_bodies.csv")).string(),
                                        ctx.side_comm, history ? trace_bytes : -1);
  }

  Progress progress(ctx.log, scene.time.progress_interval, scene.time.end);
  std::vector<BodyState> owned = engine.owned_states(0);
  session.describe("DEM", std::to_string(schedule.dem_substeps) + " substeps");
  // n_DEM substeps with the loads held constant; `timed`: part of this run's step split (the
  // steps a restart replays are not).
  auto advance = [&](std::int64_t step, const std::vector<BodyLoad>& loads, bool timed) {
    for (const BodyLoad& l : loads)
      engine.set_load(l.id, Eigen::Vector3d(l.f[0], l.f[1], l.f[2]),
                      Eigen::Vector3d(l.t[0], l.t[1], l.t[2]));
    if (timed)
      session.timed("DEM", [&] { engine.run(schedule.dem_substeps); });
    else
      engine.run(schedule.dem_substeps);
    owned = engine.owned_states(step);
  };
  if (history) {
    // Steps 0..first again, fed by the journal, each state checked against it bit for bit.
    const std::int64_t first = session.step();
    history->send_states(0, owned);
    coupler->journal_states(0, owned);
    const auto replay_start = std::chrono::steady_clock::now();
    for (std::int64_t step = 1; step <= first; ++step) {
      const std::vector<BodyLoad> loads = history->receive_loads(step);
      coupler->journal_loads(step, loads);
      advance(step, loads, false);
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
  session.on_checkpoint([&](const std::string& prefix, const CheckpointHeader& header) {
    write_dem_checkpoint(prefix, coupler->flush_journal(), header,
                         trace ? trace->flushed_bytes() : -1, ctx.side_comm);
  });
  coupler->send_states(session.step(), owned);
  session.steps_begin(coupler->times());
  const BodyWatchLimits limits = body_watch_limits(scene);
  std::string trouble;  // the bodies' diagnosis, once found (the first finding stays)
  while (session.ongoing()) {
    const std::int64_t step = session.next_step();
    const std::vector<BodyLoad> loads = coupler->receive_loads(step);
    advance(step, loads, true);
    const double time = session.time_of(step);
    if (session.output_at(step) && trace) {
      trace->write(time, owned, loads);
      snapshots->write(owned, time);
    }
    coupler->send_states(step, owned);
    progress.update(step, time);
    if (session.agrees() && trouble.empty())
      trouble =
          check_bodies(owned, step, time, setup, limits, session.agreement_at(step), ctx.side_comm);
    session.advance(trouble.empty() ? 0 : kBodiesUnstable);
    // The fluid's in-run rebalancing: its boxes (new or not), and when new, this step's states
    // routed by them once more (docs/scaling.md, "Rebalancing during a run").
    if (session.agrees() && session.ongoing() && schedule.rebalance_at(step)) {
      const bool moved = coupler->follow_layout();
      if (moved && ctx.rank == 0)
        ctx.log->info("step {}: the fluid cut its lattice anew; the states go by its new boxes",
                      step);
    }
  }
  session.count("bodies_owned", double(owned.size()));
  double spheres = 0;  // of the owned bodies' clumps (without LAMMPS's helper spheres)
  for (const BodyState& b : owned)
    spheres += double(setup.shapes[static_cast<size_t>(b.shape)].clump.size());
  session.count("clump_spheres", spheres);
  session.count("substeps", double(schedule.dem_substeps));
  session.count("atoms", double(engine.local_atoms()));
  session.count("ghost_atoms", double(engine.ghost_atoms()));
  const LoadTraffic& traffic = engine.load_traffic();
  const double exchanges = double(std::max<long long>(traffic.exchanges, 1));
  session.count("load_bytes_per_step", double(traffic.bytes) / exchanges);
  session.count("load_messages_per_step", double(traffic.messages) / exchanges);
  if (trace) {
    session.output(trace->path());
    session.output(snapshots->xdmf_path());
  }
  if (ctx.rank == 0) {
    // The diagnosis first: the session's report points at it.
    if (session.end() == SessionEnd::unstable && !trouble.empty()) ctx.log->error("{}", trouble);
    if (trace) ctx.log->info("bodies: {} and {}", trace->path(), snapshots->xdmf_path());
  }
  const int rc = session.finish(coupler->times());
  if (ctx.rank == 0 && replay && session.end() == SessionEnd::completed)
    ctx.log->info("replay of {}: the states of all {} steps match the recording bit for bit",
                  ctx.cli.replay, session.step());
  // The journal served the checkpoints (each holds its own copy up to its step).
  coupler.reset();
  if (!journal.empty()) {
    std::error_code ec;
    std::filesystem::remove(journal_part(journal, ctx.rank), ec);
    MPI_Barrier(ctx.side_comm);  // every part gone before the folder is looked at
  }
  if (ctx.rank == 0 && !journal.empty()) {
    std::error_code ec;
    if (std::filesystem::is_empty(checkpoint_directory(scene), ec))
      std::filesystem::remove(checkpoint_directory(scene), ec);
  }
  return rc;
}

}  // namespace lbdem
