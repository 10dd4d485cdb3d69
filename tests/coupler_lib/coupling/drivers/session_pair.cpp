// session_pair: both sides of a coupling session in one MPMD test, as preCICE tests its
// participants. The same program runs as the fluid (--side fluid) and as the DEM (--side dem);
// each loops `while (session.ongoing()) { ...; session.advance(flags, accept); }` over a
// hand-made schedule (20 steps, a checkpoint every 5; the scene's fluid.stability.interval is
// 4, so the programs agree at steps 4, 5, 8, 10, 12, 15, 16 and 20) with no physics, and
// checks what the session did against what the scenario must give:
//
//   lockstep         both complete 20 steps; checkpoints at 5, 10, 15, 20 on both sides;
//                    checkpoint_keep (2) halves left per side; accept ran at every step
//   fluid_unstable   the fluid's last rank flags itself unstable from step 6 on: both stop at
//                    the next agreement step (8) with exit 3, accept did not run for step 8,
//                    the last good checkpoint is step 5
//   dem_unstable     the same, found by the DEM's last rank
//   stop             the DEM's last rank receives SIGTERM at step 11: both write a
//                    checkpoint at the next agreement step (12, not a checkpoint step) and end
//                    with status 0
//
// The steps each side wrote checkpoints at are swapped over the intercommunicator and must
// be equal.
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupler_lib/app/run_app.hpp"
#include "coupler_lib/coupling/coupling_session.hpp"

namespace lbdem {
namespace {

constexpr std::int64_t kSteps = 20;
constexpr std::int64_t kCheckpointEvery = 5;

struct Expected {
  SessionEnd end;
  std::int64_t last_step;
  std::vector<std::int64_t> checkpoints;
  int exit;
};

Expected expected_of(const std::string& scenario) {
  if (scenario == "lockstep") return {SessionEnd::completed, 20, {5, 10, 15, 20}, 0};
  if (scenario == "fluid_unstable" || scenario == "dem_unstable")
    return {SessionEnd::unstable, 8, {5}, kExitUnstable};
  if (scenario == "stop") return {SessionEnd::stop_requested, 12, {5, 10, 12}, 0};
  throw std::invalid_argument("unknown scenario " + scenario);
}

void check(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("check failed: " + what);
}

int run(AppContext& ctx, const std::string& scenario) {
  const Expected want = expected_of(scenario);
  const bool fluid = ctx.side == "fluid";
  // A clean checkpoint folder (the DEM side creates it only after the handshake).
  if (fluid && ctx.rank == 0) std::filesystem::remove_all(checkpoint_directory(ctx.scene));
  World world = connect(ctx);
  Schedule schedule;
  schedule.dt = 1.0;
  schedule.steps = kSteps;
  schedule.checkpoint_interval = kCheckpointEvery;
  CouplingSession session(ctx, ctx.scene, schedule, &world);
  check(session.agrees(), "a live session without overlap agrees");

  const bool last_rank = ctx.rank == ctx.size - 1;
  std::vector<std::int64_t> written;
  session.on_checkpoint([&](const std::string& prefix, const CheckpointHeader& h) {
    check(h.step == session.step(), "the header carries the completed step");
    written.push_back(h.step);
    if (ctx.rank == 0) std::ofstream(prefix + (fluid ? ".fluid.h5" : ".dem.h5")) << h.step;
  });
  std::int64_t accepted = 0;
  while (session.ongoing()) {
    const std::int64_t step = session.next_step();
    int flags = 0;
    if (last_rank && step >= 6) {
      if (scenario == "fluid_unstable" && fluid) flags = kFluidUnstable;
      if (scenario == "dem_unstable" && !fluid) flags = kBodiesUnstable;
    }
    if (scenario == "stop" && !fluid && last_rank && step == 11) std::raise(SIGTERM);
    session.timed("work", [] {});
    session.advance(flags, [&] { ++accepted; });
  }
  const int rc = session.finish({});

  const std::string where = ctx.program + " rank " + std::to_string(ctx.rank) + ": ";
  check(session.end() == want.end, where + "how the run ended");
  check(session.step() == want.last_step, where + "ended at step " +
                                              std::to_string(session.step()) + ", expected " +
                                              std::to_string(want.last_step));
  check(rc == want.exit, where + "exit status " + std::to_string(rc));
  check(written == want.checkpoints, where + "checkpoint steps");
  const std::int64_t want_accepted =
      want.end == SessionEnd::unstable ? want.last_step - 1 : want.last_step;
  check(accepted == want_accepted, where + "accepted " + std::to_string(accepted) + " steps");
  check(session.last_checkpoint() == checkpoint_prefix(ctx.scene, want.checkpoints.back()),
        where + "last checkpoint " + session.last_checkpoint());

  // Both sides wrote at the same steps (rank 0 of each swaps its list).
  if (ctx.rank == 0) {
    std::vector<std::int64_t> theirs(written.size() + 8, -1);
    MPI_Status st;
    MPI_Sendrecv(written.data(), int(written.size()), MPI_INT64_T, 0, 77, theirs.data(),
                 int(theirs.size()), MPI_INT64_T, 0, 77, world.inter(), &st);
    int n = 0;
    MPI_Get_count(&st, MPI_INT64_T, &n);
    theirs.resize(std::size_t(n));
    check(theirs == written, where + "the other side checkpointed at other steps");
    // Pruning left the newest checkpoint_keep halves of this side.
    int halves = 0;
    for (const auto& e : std::filesystem::directory_iterator(checkpoint_directory(ctx.scene)))
      if (e.path().string().ends_with(fluid ? ".fluid.h5" : ".dem.h5")) ++halves;
    const int keep = std::min<int>(ctx.scene.coupling.checkpoint_keep, int(written.size()));
    check(halves == keep,
          where + std::to_string(halves) + " halves left, expected " + std::to_string(keep));
  }
  if (ctx.rank == 0) std::printf("%s: scenario %s passed\n", ctx.program.c_str(), scenario.c_str());
  return 0;
}

}  // namespace
}  // namespace lbdem

int main(int argc, char** argv) {
  // --side fluid|dem and --scenario NAME are this driver's; the rest goes to the common main.
  std::string side = "fluid", scenario = "lockstep";
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--side" || a == "--scenario") && i + 1 < argc)
      (a == "--side" ? side : scenario) = argv[++i];
    else
      argv[out++] = argv[i];
  }
  argc = out;
  const lbdem::AppInfo info{side, "session_pair_" + side, "coupling session test, " + side};
  return lbdem::run_app(
      argc, argv, info, [](lbdem::AppContext&) {},
      [&scenario](lbdem::AppContext& ctx) { return lbdem::run(ctx, scenario); });
}
