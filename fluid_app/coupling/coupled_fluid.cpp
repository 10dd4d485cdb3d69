#include "fluid_app/coupling/coupled_fluid.hpp"

#include <algorithm>
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
#include "coupler_lib/coupling/coupling_session.hpp"
#include "coupler_lib/coupling/fluid_coupler.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/output/gather.hpp"
#include "coupler_lib/scene/band_calibration.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "fluid_app/coupling/fluid_checkpoint.hpp"
#include "fluid_app/coupling/momentum_audit.hpp"
#include "fluid_app/coupling/settling_force.hpp"
#include "fluid_app/coupling/solver_binding.hpp"
#include "fluid_app/coupling/state_feed.hpp"
#include "fluid_app/hlbm/body_field.hpp"
#include "fluid_app/hlbm/momentum_exchange.hpp"
#include "fluid_app/hlbm/penalty_loads.hpp"
#include "fluid_app/parallel/balance.hpp"
#include "fluid_app/parallel/rebalance.hpp"
#include "fluid_app/run/fluid_run.hpp"
#include "fluid_app/run/run_watch.hpp"

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
void restore_covered(hlbm::PenaltyLoads<T>& loads, const hlbm::BodyField<T>& bodies,
                     const std::vector<CoveredRecord>& records, bool same_layout, int rank,
                     MPI_Comm comm) {
  using Memory = typename hlbm::PenaltyLoads<T>::CoveredMemory;
  std::map<std::int64_t, Memory> mine;
  for (const auto& m : loads.covered_memory(bodies)) mine[m.id] = Memory{m.id, {}, {}, {}};
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
    // Every rank summed L about the same centre (it wraps alike on every rank).
    for (int a = 0; a < 3; ++a) {
      it->second.covered[a] += r.covered[a];
      it->second.covered_moment[a] += r.covered_moment[a];
      it->second.centre[a] = r.centre[a];
    }
  }
  for (const auto& [id, m] : mine) loads.restore_covered(bodies, m);
}

// This rank's work at the end of the run: its cells, those a body covers (d < 1), split into
// the band (0 < d < 1) and the bodies' interiors (d = 0), where the porous kernel and the load
// sums run; the cells of the rows the kernel runs on a porous path (every row with a covered
// cell, FluidSolver::porous_row_cells); the bodies in its table and those that cover at least
// one of its cells; what its halo exchange sent per lattice step (the tables of
// tools/scaling.py's cost model).
template <class T>
void count_work(CouplingSession& session, const FluidSolver<T>& solver,
                double covered_cell_weight) {
  const LocalBox& box = solver.box();
  const PorousField<T>& field = solver.porous();
  double covered = 0, interior = 0;
  std::vector<char> touching(field.bodies.size(), 0);
  if (field.active)
    for (int z = 1; z <= box.n[2]; ++z)
      for (int y = 1; y <= box.n[1]; ++y)
        for (int x = 1; x <= box.n[0]; ++x) {
          const std::size_t c = std::size_t(box.index(x, y, z));
          const float d = field.d[c];
          covered += d < 1.0f;
          interior += d == 0.0f;
          const std::int32_t b = field.body[c];
          if (d < 1.0f && b >= 0 && std::size_t(b) < touching.size()) touching[std::size_t(b)] = 1;
        }
  double touched = 0;
  for (char t : touching) touched += t;
  const HaloTraffic& halo = solver.halo_traffic();
  const double exchanges = double(std::max<long long>(halo.exchanges, 1));
  session.count("cells", double(box.interior_cells()));
  session.count("cells_with_ghosts", double(box.cells_with_ghosts()));
  session.count("covered_cells", covered);
  session.count("band_cells", covered - interior);
  session.count("body_interior_cells", interior);
  session.count("porous_row_cells", solver.porous_row_cells());
  session.count("bodies_in_table", double(field.bodies.size()));
  session.count("bodies_touching", touched);
  session.count("weighted_work",
                weighted_work(double(box.interior_cells()), covered, covered_cell_weight));
  session.count("halo_bytes_per_step", double(halo.bytes) / exchanges);
  session.count("halo_messages_per_step", double(halo.messages) / exchanges);
}

// Collective: the work of the lattice as the porosity field shows it now (rebalance.hpp).
template <class T>
CheckpointWork measured_work(const FluidSolver<T>& solver, double covered_cell_weight) {
  const PorousField<T>& field = solver.porous();
  return measure_work(solver.box(),
                      field.active ? std::span<const float>(field.d) : std::span<const float>(),
                      covered_cell_weight, solver.comm());
}

// An in-run rebalancing step (fluid.rebalance_interval; both programs are at step `step`, the
// states of which `states` holds and the bodies are embedded). Above fluid.rebalance_above the
// lattice is cut anew by the measured work, exactly as a restart from a checkpoint of this step
// would cut it (restart_layout), unless the new blocks would hold no lower imbalance
// (imbalance_of_cuts, counted before anything moves): the populations move to the new blocks, the
// bodies are embedded anew from this step's states (the DEM sends them again when the boxes
// changed), and the covered momentum of the step goes whole to the lowest rank that now holds the
// body. The run then continues as that restart would, bit for bit. Either way the boxes are
// announced to the DEM side, which routes by them.
template <class T, class Embed>
void rebalance(AppContext& ctx, FluidRun<T>& run, FluidCoupler& coupler, StateFeed& feed,
               const std::vector<BodyState>& states, std::int64_t step, const Embed& embed,
               std::unique_ptr<hlbm::BodyField<T>>& bodies, hlbm::PenaltyLoads<T>& penalty_loads) {
  const FluidParams& fluid = *ctx.scene.fluid;
  CheckpointWork work = measured_work(run.solver(), fluid.covered_cell_weight);
  work.layout = run.layout_weights();
  const LayoutChoice choice = restart_layout(fluid, work, ctx.size);
  const PorousField<T>& field = run.solver().porous();
  const double cut = choice.same_as_checkpoint
                         ? work.imbalance
                         : imbalance_of_cuts(run.solver().box(),
                                             field.active ? std::span<const float>(field.d)
                                                          : std::span<const float>(),
                                             fluid.covered_cell_weight, choice.weights,
                                             run.solver().decomposition().dims(), ctx.side_comm);
  if (choice.same_as_checkpoint || cut >= work.imbalance) {
    if (ctx.rank == 0)
      ctx.log->info("step {}: load imbalance of the weighted work {:.3f}{}: cuts kept", step,
                    work.imbalance,
                    choice.same_as_checkpoint
                        ? fmt::format(", at most fluid.rebalance_above = {}", fluid.rebalance_above)
                        : fmt::format(" (new cuts by the measured work would give {:.3f})", cut));
    coupler.announce_layout(geometry_of(ctx.scene, run.solver().box(), {}).mine);
    return;
  }
  std::vector<CoveredRecord> covered;
  for (const auto& m : penalty_loads.covered_memory(*bodies))
    covered.push_back({ctx.rank, m.id, m.covered, m.covered_moment, m.centre});
  covered = gather_to_root(std::span<const CoveredRecord>(covered), ctx.side_comm);
  broadcast(covered, 0, ctx.side_comm);
  bodies.reset();
  run.relayout(choice.weights,
               fmt::format("rebalanced at step {}: load imbalance {:.3f} measured, above "
                           "fluid.rebalance_above = {}",
                           step, work.imbalance, fluid.rebalance_above));
  const bool moved = coupler.announce_layout(geometry_of(ctx.scene, run.solver().box(), {}).mine);
  const std::vector<BodyState>& now = moved ? feed.start(step) : states;
  bodies = embed();
  bodies->update(now);
  penalty_loads = hlbm::PenaltyLoads<T>{};
  restore_covered(penalty_loads, *bodies, covered, false, ctx.rank, ctx.side_comm);
  const double after = measured_work(run.solver(), fluid.covered_cell_weight).imbalance;
  if (ctx.rank == 0)
    ctx.log->info(
        "step {}: load imbalance of the weighted work {:.3f} -> {:.3f} (lattice cut "
        "anew by the measured work)",
        step, work.imbalance, after);
}

template <class T>
int run_typed(AppContext& ctx) {
  const Scene& scene = ctx.scene;
  const bool replay = !ctx.cli.replay.empty();
  // The handshake comes first so a wrong partner is reported before any heavy set-up.
  World world;
  if (!replay) world = connect(ctx);

  const std::vector<Shape> shapes = build_scene_shapes(scene);
  CouplingSession session(ctx, scene, coupled_schedule(scene, shapes), replay ? nullptr : &world);
  if (scene.fluid->hydrodynamic_radius == HydrodynamicRadius::calibrated)
    ctx.log->info(
        "hydrodynamic radius calibrated: the band's excess at tau {} ({} lookup) is {:+.3f} "
        "cells, so the fluid sees every surface moved inward by that much (docs/method.md)",
        scene.fluid->tau, word_of(kPorosityLookupWords, scene.fluid->porosity_lookup),
        *band_radius_excess_cells(scene.fluid->tau, scene.fluid->porosity_lookup));
  if (scene.fluid->hydrodynamic_radius == HydrodynamicRadius::calibrated &&
      !band_calibration_checked(scene.fluid->tau))
    ctx.log->warn(
        "{}: fluid.tau {} lies outside {}, where the calibrated drag was checked (docs/method.md, "
        "\"Hydrodynamic radius calibration\"): the measured offset applies, its accuracy is not "
        "known there",
        scene.file, scene.fluid->tau, band_calibration_checked_range());
  // A restart's layout comes from the checkpoint's record of the work (rebalance.hpp).
  std::string restart_from;
  LayoutChoice layout;
  if (!ctx.cli.restart.empty()) {
    try {
      restart_from = restart_prefix(ctx.cli.restart);
      layout =
          restart_layout(*scene.fluid, read_checkpoint_work(restart_from, ctx.side_comm), ctx.size);
    } catch (const std::runtime_error& e) {
      throw SideError(e.what());
    }
  }
  FluidRun<T> run(ctx, shapes, restart_from.empty() ? nullptr : &layout);
  // run.solver() is replaced when the lattice is cut anew during the run (rebalance below):
  // nothing keeps a reference to it across steps. Its ranks are the side's, in order.
  const int solver_rank = ctx.rank;
  std::optional<FluidRestart> restart;
  std::vector<T> restored;  // this rank's populations from the checkpoint
  if (!restart_from.empty()) {
    try {
      restart = read_fluid_checkpoint(restart_from, session.header(0), run.solver(), restored);
      session.resume(restart_from, restart->header.step);
      ctx.log->info("restart from {} at step {} (t = {:.6e} s; written by {} fluid ranks)",
                    restart_from, restart->header.step, restart->header.time,
                    restart->header.fluid_ranks);
    } catch (const std::runtime_error& e) {
      throw SideError(e.what());
    }
  }
  RunWatch<T> watch(ctx, run, restart ? restart->lengths.series : -1);
  const FluidGeometry geometry = geometry_of(scene, run.solver().box(), shapes);
  std::unique_ptr<FluidCoupler> coupler =
      replay ? std::make_unique<FluidCoupler>(ctx, ctx.cli.replay, geometry)
             : std::make_unique<FluidCoupler>(world, geometry);

  hlbm::LatticeFrame frame{Eigen::Vector3d::Zero(), scene.fluid->units};
  const hlbm::Subdomain sub = hlbm::subdomain_of(run.solver(), *scene.fluid);
  // The bodies on this rank's block (made anew with the block when the lattice is re-cut).
  auto embed = [&] {
    return std::make_unique<hlbm::BodyField<T>>(
        shapes, hlbm::subdomain_of(run.solver(), *scene.fluid), frame, run.solver().porous(),
        scene.fluid->porosity_lookup);
  };
  std::unique_ptr<hlbm::BodyField<T>> bodies = embed();
  hlbm::PenaltyLoads<T> penalty_loads;
  const SettlingForce settling = settling_force(scene, shapes);
  if (settling.active) {
    // The controller (if any) adds its correction to this feed-forward (or, with
    // feed_forward: false, finds the force alone, as in the paper); without it the
    // compensating force simply adds to the scene's uniform body force.
    if (run.control()) {
      if (scene.fluid->control.feed_forward)
        run.control()->set_feed_forward(settling.fluid_force_lattice);
    } else {
      auto force = run.solver().uniform_force();
      for (int a = 0; a < 3; ++a) force[a] += settling.fluid_force_lattice[a];
      run.solver().set_uniform_force(force);
    }
    ctx.log->info("{}", settling.description);
  }

  // Triply periodic box: the momentum audit at the coupling output steps (with or without
  // settling: without external forces it audits the exchange alone).
  std::unique_ptr<MomentumAudit> audit;
  if (sub.periodic[0] && sub.periodic[1] && sub.periodic[2] &&
      session.schedule().output_interval > 0) {
    std::filesystem::path dir(scene.dem->output.directory);
    if (dir.is_relative()) dir = std::filesystem::path(scene.file).parent_path() / dir;
    if (ctx.rank == 0) std::filesystem::create_directories(dir);
    audit = std::make_unique<MomentumAudit>((dir / (scene.name + "_momentum.csv")).string(), scene,
                                            shapes, settling.net_weight, ctx.side_comm,
                                            restart ? restart->lengths.momentum : -1);
  }
  if (restart) {
    // After the run's own set-up of forces (feed-forward), which the memory overrides.
    run.solver().restore(restart->memory);
    if (run.control()) run.control()->restore(restart->control_integral);
    run.solver().set_interior_populations(restored);
    restored = {};
  }
  const bool penalty = scene.fluid->loads == LoadMethod::penalization;

  StateFeed feed(*coupler, scene.coupling.overlap);
  const auto& first = feed.start(session.step());
  if (audit && !restart) audit->write(0, 0.0, run.solver(), first);
  bodies->update(first);
  if (restart)
    restore_covered(penalty_loads, *bodies, restart->covered, layout.same_as_checkpoint,
                    solver_rank, ctx.side_comm);
  else
    run.start();
  // Every checkpoint holds a state that passed the stability check.
  watch.check_also_at([&](long step) { return session.checkpoint_at(step); });
  session.on_checkpoint([&](const std::string& prefix, const CheckpointHeader& header) {
    std::vector<CoveredRecord> covered;
    for (const auto& m : penalty_loads.covered_memory(*bodies))
      covered.push_back({solver_rank, m.id, m.covered, m.covered_moment, m.centre});
    SeriesLengths lengths;
    lengths.series = watch.series_bytes();
    if (audit) lengths.momentum = audit->bytes();
    CheckpointWork work = measured_work(run.solver(), scene.fluid->covered_cell_weight);
    work.layout = run.layout_weights();
    if (ctx.rank == 0)
      ctx.log->info("checkpoint at step {}: load imbalance of the weighted work {:.3f}",
                    header.step, work.imbalance);
    write_fluid_checkpoint(prefix, header, run.solver(),
                           run.control() ? run.control()->integral() : std::array<double, 3>{},
                           covered, lengths, work);
  });

  session.steps_begin(coupler->times());
  while (session.ongoing()) {
    const std::int64_t step = session.next_step();
    session.timed("lattice", [&] { run.step(); });
    const auto loads = session.timed("porosity + momentum exchange", [&] {
      return penalty ? penalty_loads.loads(*bodies, step)
                     : hlbm::momentum_exchange(*bodies, hlbm::populations_of(run.solver()), step);
    });
    feed.send(step, loads);
    // The audit, the agreement and a checkpoint need the states of this very step (a brief
    // stop of the overlap).
    const bool audit_now = audit && session.output_at(step);
    const auto& states = feed.next(step, audit_now || session.agreement_at(step));
    if (audit_now) audit->write(step, session.time_of(step), run.solver(), states);
    // The states are embedded only once both programs found this step sound.
    session.advance(watch.stopped() ? kFluidUnstable : 0, [&] {
      if (feed.fresh())
        session.timed("porosity + momentum exchange", [&] { bodies->update(states); });
    });
    if (session.ongoing() && session.schedule().rebalance_at(step))
      session.timed("rebalancing", [&] {
        rebalance(ctx, run, *coupler, feed, states, step, embed, bodies, penalty_loads);
      });
  }
  if (session.end() == SessionEnd::completed) feed.finish(session.step());
  count_work(session, run.solver(), scene.fluid->covered_cell_weight);
  session.count("steps_per_s", run.steps_per_s_after_first_line());
  const int rc = watch.finish();
  const int end = session.finish(coupler->times());
  if (end != 0) return end;
  if (replay && session.end() == SessionEnd::completed)
    ctx.log->info("replay of {}: the loads of all {} steps match the recording bit for bit",
                  ctx.cli.replay, session.step());
  return session.end() == SessionEnd::completed ? rc : 0;
}

}  // namespace

int run_coupled_fluid(AppContext& ctx) {
  return ctx.scene.fluid->precision == Precision::float32 ? run_typed<float>(ctx)
                                                          : run_typed<double>(ctx);
}

}  // namespace lbdem
