// fluid_driver: the fluid side of the coupler's MPMD tests. Announces uneven slabs as its
// subdomains, checks every step that it receives exactly the bodies that can reach its box
// (with their exact trajectory states), and answers with known partial loads.
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include "coupler_lib/app/run_app.hpp"
#include "coupler_lib/coupling/fluid_coupler.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "tests/coupler_lib/coupling/drivers/synthetic.hpp"

namespace lbdem {
namespace {

void fail_check(const std::string& what) {
  throw std::runtime_error("check failed: " + what);
}

int run(AppContext& ctx, const synthetic::DriverOptions& opt) {
  const Scene& scene = ctx.scene;
  if (opt.exit_at_start) {
    std::fprintf(stderr, "fluid_driver: exiting at start on purpose\n");
    std::fflush(stderr);
    std::_Exit(3);
  }
  if (opt.finish_at_start) return 0;
  if (!scene.coupled()) {
    std::printf("fluid_driver: the scene is not coupled, nothing to exchange\n");
    return 0;
  }
  FluidGeometry geo;
  geo.mine = synthetic::fluid_box(scene, ctx.rank, ctx.size);
  geo.domain = synthetic::domain_box(scene);
  geo.periodic = synthetic::periodic_axes(scene);
  geo.shape_radius = synthetic::shape_radii(scene);
  geo.margin = stencil_margin(scene);

  std::optional<World> world;
  std::optional<FluidCoupler> coupler;
  if (ctx.cli.replay.empty()) {
    world.emplace(connect(ctx, {opt.announce_version}));
    coupler.emplace(*world, geo);
  } else {
    coupler.emplace(ctx, ctx.cli.replay, geo);
  }
  const FluidLayout& layout = coupler->layout();
  Schedule sched = make_schedule(scene, scene.fluid->units.dt, scene.dem->dt);
  if (opt.steps >= 0) sched.steps = opt.steps;
  std::int64_t seen = 0;
  for (std::int64_t step = 0; step < sched.steps; ++step) {
    if (step == opt.throw_at_step && ctx.rank == opt.throw_rank)
      throw std::runtime_error("synthetic failure on fluid rank " + std::to_string(ctx.rank) +
                               " at step " + std::to_string(step));
    const std::vector<BodyState> got = coupler->receive_states(step);
    std::set<std::int64_t> expected;
    for (std::int64_t id = 0; id < static_cast<std::int64_t>(scene.bodies.size()); ++id) {
      const BodyState b = synthetic::trajectory(scene, id, step);
      if (synthetic::touches(layout, layout.boxes[static_cast<size_t>(ctx.rank)], b.x,
                             layout.reach(b.shape)))
        expected.insert(id);
    }
    std::set<std::int64_t> received;
    for (const BodyState& s : got) {
      received.insert(s.id);
      const BodyState t = synthetic::trajectory(scene, s.id, step);
      for (int d = 0; d < 3; ++d)
        if (s.x[d] != t.x[d] || s.v[d] != t.v[d])
          fail_check("body " + std::to_string(s.id) + " at step " + std::to_string(step) +
                     " arrived with a wrong position or velocity");
      if (s.step != step || s.shape != t.shape) fail_check("wrong step or shape");
    }
    if (received != expected || received.size() != got.size())
      fail_check("fluid rank " + std::to_string(ctx.rank) + " at step " + std::to_string(step) +
                 " received " + std::to_string(got.size()) + " bodies, expected " +
                 std::to_string(expected.size()));
    seen += static_cast<std::int64_t>(got.size());
    std::vector<BodyLoad> partials;
    for (const BodyState& s : got) partials.push_back(synthetic::partial(s, ctx.rank, step));
    if (step == opt.perturb_step && !partials.empty() && ctx.rank == 0)
      partials.front().f[1] = std::nextafter(partials.front().f[1], 1e300);
    coupler->send_loads(step + opt.load_label, partials);
  }
  long long total = 0, mine = seen;
  MPI_Allreduce(&mine, &total, 1, MPI_LONG_LONG, MPI_SUM, ctx.side_comm);
  if (total < sched.steps) fail_check("too few bodies reached the fluid ranks to test anything");
  const CouplingTimes t = coupler->times();
  ctx.log->info(
      "fluid driver: {} steps, {} fluid ranks, all checks passed; coupling {:.4f} s in {} calls "
      "(waiting {:.4f} s, exchange {:.4f} s)",
      sched.steps, ctx.size, t.total_s, t.calls, t.idle_s, t.exchange_s());
  std::printf("fluid rank %d: %lld body states received and checked\n", ctx.rank,
              static_cast<long long>(seen));
  return 0;
}

}  // namespace
}  // namespace lbdem

int main(int argc, char** argv) {
  const lbdem::synthetic::DriverOptions opt = lbdem::synthetic::take_driver_options(argc, argv);
  const lbdem::AppInfo info{"fluid", "fluid_driver", "coupler test driver, fluid side"};
  return lbdem::run_app(
      argc, argv, info, [](lbdem::AppContext&) {},
      [&opt](lbdem::AppContext& ctx) { return lbdem::run(ctx, opt); });
}
