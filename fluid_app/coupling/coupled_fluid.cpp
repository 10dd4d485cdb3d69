#include "fluid_app/coupling/coupled_fluid.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

#include "coupler_lib/coupling/fluid_coupler.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
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

template <class T>
int run_typed(AppContext& ctx) {
  const Scene& scene = ctx.scene;
  const bool replay = !ctx.cli.replay.empty();
  // The handshake comes first so a wrong partner is reported before any heavy set-up.
  World world;
  if (!replay) world = connect(ctx);

  const std::vector<Shape> shapes = build_scene_shapes(scene);
  FluidRun<T> run(ctx);
  FluidSolver<T>& solver = run.solver();
  RunWatch<T> watch(ctx, run);
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
                                            shapes, settling.net_weight, solver.comm());
  }
  const bool penalty = scene.fluid->loads == LoadMethod::penalization;

  StateFeed feed(*coupler, scene.coupling.overlap);
  const auto& first = feed.start();
  if (audit) audit->write(0, 0.0, solver, first);
  bodies.update(first);
  run.start();
  while (!run.done() && !watch.stopped()) {
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
    if (watch.stopped()) break;
    // The audit needs the states of this very step (a brief stop of the overlap).
    const bool audit_now = audit && schedule.output_at(step);
    const auto& states = feed.next(step, audit_now);
    if (audit_now) audit->write(step, double(step) * scene.fluid->units.dt, solver, states);
    if (!feed.fresh()) continue;
    t = Clock::now();
    bodies.update(states);
    bodies_s += seconds_since(t);
  }
  if (!watch.stopped()) feed.finish(solver.steps());
  if (const std::int64_t n = solver.steps(); n > 0) {
    const CouplingTimes c = coupler->times();
    ctx.log->info(
        "time per coupled step (fluid rank 0): lattice {:.3e} s, porosity + momentum exchange "
        "{:.3e} s, exchange {:.3e} s, idle (waiting for dem_app) {:.3e} s",
        lattice_s / double(n), bodies_s / double(n), c.exchange_s() / double(n),
        c.idle_s / double(n));
  }
  const int rc = watch.finish();
  if (watch.stopped()) {
    // The DEM side is waiting for loads that will never come: end the whole job. The
    // diagnosis and the last good state were written by the stability watch.
    throw SideError(
        "the fluid became unstable (diagnosis above, last good state written); stopping dem_app");
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
