#include "fluid_app/coupling/coupled_fluid.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/coupling/checkpoint_files.hpp"
#include "coupler_lib/coupling/fluid_coupler.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/coupling/stop_request.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/band_calibration.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "fluid_app/coupling/fluid_checkpoint.hpp"
#include "fluid_app/coupling/momentum_audit.hpp"
#include "fluid_app/coupling/settling_force.hpp"
#include "fluid_app/coupling/state_feed.hpp"
#include "fluid_app/fluid_run.hpp"
#include "fluid_app/hlbm/body_field.hpp"
#include "fluid_app/output/run_watch.hpp"

namespace lbdem {

namespace {

FluidGeometry geometry_of(const Scene& scene, const LocalBox& box,
                          const std::vector<Shape>& shapes) {
  const FluidParams& f = *scene.fluid;
  FluidGeometry g;
  for (int a = 0; a < 3; ++a) {
    g.mine.lo[a] = box.offset[a] * f.dx;
    g.mine.hi[a] = (box.offset[a] + box.n[a]) * f.dx;
    g.domain.lo[a] = 0;
    g.domain.hi[a] = f.domain[a];
    g.periodic[a] = f.periodic(a);
  }
  for (const auto& s : shapes) g.shape_radius.push_back(s.bounding_radius);
  g.margin = stencil_margin(scene);
  return g;
}

// Q and L of the checkpoint's step for the bodies this rank tracks. On the decomposition that
// wrote them each rank takes its own; on another one, the sum over the old ranks goes to the
// lowest new rank that tracks the body (the DEM sums the partials: the same load up to
// round-off).
template <class T>
void restore_covered(hlbm::BodyField<T>& bodies, const std::vector<CoveredRecord>& records,
                     bool same_layout, int rank, MPI_Comm comm) {
  using Memory = typename hlbm::BodyField<T>::CoveredMemory;
  std::map<std::int64_t, Memory> mine;
  for (const auto& m : bodies.covered_memory()) mine[m.id] = Memory{m.id, {}, {}};
  std::int64_t ids = 0;
  for (const CoveredRecord& r : records) ids = std::max(ids, r.id + 1);
  std::vector<int> lowest(static_cast<std::size_t>(ids), std::numeric_limits<int>::max());
  for (const auto& [id, m] : mine)
    if (id < ids) lowest[static_cast<std::size_t>(id)] = rank;
  MPI_Allreduce(MPI_IN_PLACE, lowest.data(), static_cast<int>(ids), MPI_INT, MPI_MIN, comm);
  for (const CoveredRecord& r : records) {
    const bool take = same_layout ? r.rank == rank : lowest[static_cast<std::size_t>(r.id)] == rank;
    if (!take) continue;
    const auto it = mine.find(r.id);
    const bool zero =
        r.covered == std::array<double, 3>{} && r.covered_moment == std::array<double, 3>{};
    if (it == mine.end()) {
      if (same_layout && !zero)
        throw SideError("restart: body " + std::to_string(r.id) +
                        " covered fluid on this rank at the checkpoint but is not here now");
      continue;
    }
    for (int a = 0; a < 3; ++a) {
      it->second.covered[a] += r.covered[a];
      it->second.covered_moment[a] += r.covered_moment[a];
    }
  }
  for (const auto& [id, m] : mine) bodies.restore_covered(m);
}

template <class T>
int run_typed(AppContext& ctx) {
  const Scene& scene = ctx.scene;
  const bool replay = !ctx.cli.replay.empty();
  // The handshake comes first so a wrong partner is reported before any heavy set-up.
  World world;
  if (!replay) world = connect(ctx);

  // Checkpoints need both programs at the same step; with overlap they are one step apart
  // (the scene refuses checkpoint_interval there, and stop signals keep their default).
  const bool checkpoints = !replay && !scene.coupling.overlap;
  if (checkpoints) install_stop_handlers();
  const int dem_ranks = replay ? 0 : world.peer().size;

  const std::vector<Shape> shapes = build_scene_shapes(scene);
  if (scene.fluid->hydrodynamic_radius == "calibrated")
    ctx.log->info(
        "hydrodynamic radius calibrated: the band's excess at tau {} ({} lookup) is {:+.3f} "
        "cells, so the fluid sees every surface moved inward by that much (docs/method.md)",
        scene.fluid->tau, scene.fluid->porosity_lookup,
        *band_radius_excess_cells(scene.fluid->tau, scene.fluid->porosity_lookup));
  FluidRun<T> run(ctx);
  FluidSolver<T>& solver = run.solver();
  int solver_rank = 0;
  MPI_Comm_rank(solver.comm(), &solver_rank);
  std::optional<FluidRestart> restart;
  std::vector<T> restored;  // this rank's populations from the checkpoint
  if (!ctx.cli.restart.empty()) {
    try {
      const std::string prefix = restart_prefix(ctx.cli.restart);
      remember_checkpoint(prefix);
      restart = read_fluid_checkpoint(
          prefix, make_checkpoint_header(scene, "fluid", 0, 0, ctx.size, dem_ranks), solver,
          restored);
      ctx.log->info("restart from {} at step {} (t = {:.6e} s; written by {} fluid ranks)", prefix,
                    restart->header.step, restart->header.time, restart->header.fluid_ranks);
    } catch (const std::runtime_error& e) {
      throw SideError(e.what());
    }
  }
  RunWatch<T> watch(ctx, run, restart ? restart->lengths.series : -1);
  const FluidGeometry geometry = geometry_of(scene, solver.box(), shapes);
  std::unique_ptr<FluidCoupler> coupler =
      replay ? std::make_unique<FluidCoupler>(ctx, ctx.cli.replay, geometry)
             : std::make_unique<FluidCoupler>(world, geometry);

  hlbm::Subdomain sub{solver.box(), geometry.periodic};
  hlbm::LatticeFrame frame{Eigen::Vector3d::Zero(), scene.fluid->units};
  hlbm::BodyField<T> bodies(shapes, sub, frame, solver.porous(),
                            hlbm::porosity_lookup_from(scene.fluid->porosity_lookup));
  const SettlingForce settling = settling_force(scene, shapes);
  if (settling.active) {
    // The controller (if any) adds its correction to this feed-forward (or, with
    // feed_forward: false, finds the force alone, as in the paper); without it the
    // compensating force simply adds to the scene's uniform body force.
    if (scene.fluid->control.enabled) {
      if (scene.fluid->control.feed_forward)
        solver.set_feed_forward_force(settling.fluid_force_lattice);
    } else {
      auto force = solver.uniform_force();
      for (int a = 0; a < 3; ++a) force[a] += settling.fluid_force_lattice[a];
      solver.set_uniform_force(force);
    }
    ctx.log->info("{}", settling.description);
  }

  // Wall time per part of a coupled step, reported at the end (rank 0's view).
  using Clock = std::chrono::steady_clock;
  double lattice_s = 0, bodies_s = 0;
  auto seconds_since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };

  // Triply periodic settling: the momentum audit at the coupling output steps.
  const Schedule schedule = make_schedule(scene, scene.fluid->units.dt, scene.fluid->units.dt);
  std::unique_ptr<MomentumAudit> audit;
  if (settling.active && schedule.output_interval > 0) {
    std::filesystem::path dir(scene.dem->output.directory);
    if (dir.is_relative()) dir = std::filesystem::path(scene.file).parent_path() / dir;
    if (ctx.rank == 0) std::filesystem::create_directories(dir);
    audit = std::make_unique<MomentumAudit>((dir / (scene.name + "_momentum.csv")).string(), scene,
                                            shapes, settling.net_weight, solver.comm(),
                                            restart ? restart->lengths.momentum : -1);
  }
  if (restart) {
    // After the run's own set-up of forces (feed-forward), which the memory overrides.
    solver.restore(restart->memory);
    solver.set_interior_populations(restored);
    restored = {};
  }
  const bool penalty = scene.fluid->loads == LoadMethod::penalization;

  StateFeed feed(*coupler, scene.coupling.overlap);
  const auto& first = feed.start(restart ? restart->header.step : 0);
  if (audit && !restart) audit->write(0, 0.0, solver, first);
  bodies.update(first);
  if (restart)
    restore_covered(bodies, restart->covered, restart->header.fluid_ranks == ctx.size, solver_rank,
                    solver.comm());
  else
    run.start();
  // Every checkpoint holds a state that passed the stability check.
  if (checkpoints) watch.check_also_at([&](long step) { return schedule.checkpoint_at(step); });
  std::string checkpoint;  // the last one written
  bool stopped = false;
  int unstable = 0;  // kFluidUnstable | kBodiesUnstable as both programs agreed
  while (!run.done()) {
    auto t = Clock::now();
    run.step();
    lattice_s += seconds_since(t);
    const std::int64_t step = solver.steps();
    t = Clock::now();
    const auto loads = penalty
                           ? bodies.penalty_loads(step)
                           : bodies.momentum_exchange(
                                 [&](int i, CellIndex c) { return solver.population(i, c); }, step);
    bodies_s += seconds_since(t);
    feed.send(step, loads);
    if (watch.stopped() && !checkpoints) break;
    // The audit needs the states of this very step (a brief stop of the overlap).
    const bool audit_now = audit && schedule.output_at(step);
    const auto& states = feed.next(step, audit_now);
    if (audit_now) audit->write(step, double(step) * scene.fluid->units.dt, solver, states);
    // Both programs agree on stop requests and instabilities before the fluid embeds states
    // that may be non-finite.
    int flags = 0;
    if (checkpoints && agreement_at(scene, schedule, step)) {
      flags = agree_flags(
          (stop_signal() != 0 ? kStopRequested : 0) | (watch.stopped() ? kFluidUnstable : 0), world,
          step);
      unstable = flags & (kFluidUnstable | kBodiesUnstable);
      if (unstable) break;
    }
    if (feed.fresh()) {
      t = Clock::now();
      bodies.update(states);
      bodies_s += seconds_since(t);
    }
    if (!checkpoints) continue;
    stopped = (flags & kStopRequested) != 0;
    if (!stopped && !schedule.checkpoint_at(step)) continue;
    checkpoint = checkpoint_prefix(scene, step);
    std::vector<CoveredRecord> covered;
    for (const auto& m : bodies.covered_memory())
      covered.push_back({solver_rank, m.id, m.covered, m.covered_moment});
    SeriesLengths lengths;
    lengths.series = watch.series_bytes();
    if (audit) lengths.momentum = audit->bytes();
    write_fluid_checkpoint(
        checkpoint,
        make_checkpoint_header(scene, "fluid", step, double(step) * scene.fluid->units.dt, ctx.size,
                               dem_ranks),
        solver, covered, lengths);
    // Older checkpoints go only once both halves of this one exist.
    wait_for_both(world, step);
    remember_checkpoint(checkpoint);
    if (ctx.rank == 0) prune_checkpoints(scene, "fluid", scene.coupling.checkpoint_keep);
    if (stopped) break;
  }
  if (!watch.stopped() && !unstable) feed.finish(solver.steps());
  if (const std::int64_t n = solver.steps(); n > 0) {
    const CouplingTimes c = coupler->times();
    ctx.log->info(
        "time per coupled step (fluid rank 0): lattice {:.3e} s, porosity + momentum exchange "
        "{:.3e} s, exchange {:.3e} s, idle (waiting for dem_app) {:.3e} s",
        lattice_s / double(n), bodies_s / double(n), c.exchange_s() / double(n),
        c.idle_s / double(n));
  }
  const int rc = watch.finish();
  if (unstable) {
    // Both programs stop here; the one that found the problem printed the diagnosis.
    if (ctx.rank == 0) {
      if (!(unstable & kFluidUnstable))
        ctx.log->error(
            "stopped at step {}: dem_app found the bodies unstable (its diagnosis "
            "above)",
            solver.steps());
      const std::string& last = remembered_checkpoint();
      ctx.log->error("last good checkpoint: {}",
                     last.empty() ? std::string("none (set coupling.checkpoint_interval)")
                                  : last + "; continue after changing the scene with: " +
                                        restart_command(scene, last, ctx.size, dem_ranks));
    }
    return kExitUnstable;
  }
  if (watch.stopped()) {
    // The DEM side is waiting for loads that will never come: end the whole job. The
    // diagnosis and the last good state were written by the stability watch.
    throw SideError(
        "the fluid became unstable (diagnosis above, last good state written); stopping dem_app");
  }
  if (stopped) {
    ctx.log->info("stopped on request (signal {}) at step {} (t = {:.6e} s); checkpoint: {}",
                  stop_signal() != 0 ? std::to_string(stop_signal()) : "on another rank",
                  solver.steps(), double(solver.steps()) * scene.fluid->units.dt, checkpoint);
    ctx.log->info("continue with: {}", restart_command(scene, checkpoint, ctx.size, dem_ranks));
    return 0;
  }
  ctx.log->info("coupled fluid run finished after {} steps", solver.steps());
  if (replay)
    ctx.log->info("replay of {}: the loads of all {} steps match the recording bit for bit",
                  ctx.cli.replay, solver.steps());
  return rc;
}

}  // namespace

int run_coupled_fluid(AppContext& ctx) {
  return ctx.scene.fluid->precision == "float" ? run_typed<float>(ctx) : run_typed<double>(ctx);
}

}  // namespace lbdem
