// dem_driver: the DEM side of the coupler's MPMD tests. Owns a different subset of the bodies
// every step (as LAMMPS migrates them), sends their states in a step-dependent order, checks
// that each reduced load is exactly the fluid-rank-ordered sum of the partials the fluid
// driver made, and integrates the reduced torque into the angular velocity.
#include <cmath>
#include <cstdio>
#include <optional>

#include "coupler_lib/app/run_app.hpp"
#include "coupler_lib/coupling/dem_coupler.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "tests/coupler_lib/coupling/drivers/synthetic.hpp"

namespace lbdem {
namespace {

void fail_check(const std::string& what) {
  throw std::runtime_error("check failed: " + what);
}

int owner(std::int64_t id, std::int64_t step, int size) {
  return static_cast<int>((id * 7 + step) % size);
}

int run(AppContext& ctx, const synthetic::DriverOptions& opt) {
  const Scene& scene = ctx.scene;
  if (opt.exit_at_start) {
    std::fprintf(stderr, "dem_driver: exiting at start on purpose\n");
    std::fflush(stderr);
    std::_Exit(3);
  }
  if (opt.finish_at_start) return 0;
  if (!scene.coupled()) {
    std::printf("dem_driver: the scene is not coupled, nothing to exchange\n");
    return 0;
  }
  std::optional<World> world;
  std::optional<DemCoupler> coupler;
  if (ctx.cli.replay.empty()) {
    world.emplace(connect(ctx, {opt.announce_version}));
    coupler.emplace(*world, scene);
  } else {
    coupler.emplace(ctx, ctx.cli.replay);
  }
  const FluidLayout& layout = coupler->fluid_layout();
  Schedule sched = make_schedule(scene, scene.fluid->units.dt, scene.dem->dt);
  if (opt.steps >= 0) sched.steps = opt.steps;
  const size_t n = scene.bodies.size();
  std::vector<double> w(3 * n, 0.0);  // angular velocity of every body, shared after each step
  for (std::int64_t step = 0; step < sched.steps; ++step) {
    if (step == opt.throw_at_step && ctx.rank == opt.throw_rank)
      throw std::runtime_error("synthetic failure on DEM rank " + std::to_string(ctx.rank) +
                               " at step " + std::to_string(step));
    if (step == opt.finalize_at_step) {
      std::printf("dem_driver: ERROR: synthetic library error at step %lld\n",
                  static_cast<long long>(step));
      std::fflush(stdout);
      MPI_Finalize();
      std::exit(1);
    }
    std::vector<BodyState> owned;
    for (size_t k = 0; k < n; ++k) {
      const auto id = static_cast<std::int64_t>(step % 2 ? n - 1 - k : k);
      if (owner(id, step, ctx.size) != ctx.rank) continue;
      BodyState b = synthetic::trajectory(scene, id, step);
      for (int d = 0; d < 3; ++d) b.w[d] = w[3 * static_cast<size_t>(id) + static_cast<size_t>(d)];
      owned.push_back(b);
    }
    if (step == opt.perturb_step && !owned.empty() && ctx.rank == 0)
      owned.front().x[0] = std::nextafter(owned.front().x[0], 1e300);
    coupler->send_states(step, owned);
    const std::vector<BodyLoad> loads = coupler->receive_loads(step + opt.load_label);
    if (loads.size() != owned.size()) fail_check("one load per owned body");
    std::vector<double> w_new(3 * n, 0.0);
    for (size_t k = 0; k < owned.size(); ++k) {
      const BodyState& b = owned[k];
      BodyLoad sum;
      for (size_t r = 0; r < layout.boxes.size(); ++r)
        if (synthetic::touches(layout, layout.boxes[r], b.x, layout.reach(b.shape))) {
          const BodyLoad p = synthetic::partial(b, static_cast<int>(r), step);
          for (int d = 0; d < 3; ++d) {
            sum.f[d] += p.f[d];
            sum.t[d] += p.t[d];
          }
        }
      if (loads[k].id != b.id || loads[k].step != step + opt.load_label)
        fail_check("load " + std::to_string(k) + " is not for body " + std::to_string(b.id));
      for (int d = 0; d < 3; ++d)
        if (loads[k].f[d] != sum.f[d] || loads[k].t[d] != sum.t[d])
          fail_check("body " + std::to_string(b.id) + " at step " + std::to_string(step) +
                     ": reduced load is not the fluid-rank-ordered sum of the partials");
      for (int d = 0; d < 3; ++d)
        w_new[3 * static_cast<size_t>(b.id) + static_cast<size_t>(d)] =
            b.w[d] + 0.01 * loads[k].t[d];
    }
    // Every body has exactly one owner, so the sum hands each new w to every rank unchanged.
    MPI_Allreduce(w_new.data(), w.data(), static_cast<int>(w.size()), MPI_DOUBLE, MPI_SUM,
                  ctx.side_comm);
  }
  const CouplingTimes t = coupler->times();
  ctx.log->info(
      "DEM driver: {} steps, {} DEM ranks, {} fluid ranks, all checks passed; coupling {:.4f} s "
      "in {} calls (waiting {:.4f} s, exchange {:.4f} s)",
      sched.steps, ctx.size, layout.boxes.size(), t.total_s, t.calls, t.idle_s, t.exchange_s());
  return 0;
}

}  // namespace
}  // namespace lbdem

int main(int argc, char** argv) {
  const lbdem::synthetic::DriverOptions opt = lbdem::synthetic::take_driver_options(argc, argv);
  const lbdem::AppInfo info{"dem", "dem_driver", "coupler test driver, DEM side"};
  return lbdem::run_app(
      argc, argv, info, [](lbdem::AppContext&) {},
      [&opt](lbdem::AppContext& ctx) { return lbdem::run(ctx, opt); });
}
