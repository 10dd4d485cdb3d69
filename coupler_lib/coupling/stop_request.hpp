#pragma once
// Stopping a coupled run on request: SIGTERM or SIGINT (what batch schedulers send before the
// time limit) only sets a flag here; at the next exchange step both programs agree on it
// (one reduction over MPI_COMM_WORLD, which holds the ranks of both), write a checkpoint and
// end with status 0. A signal that reaches a single rank of either program is enough. The same
// reduction carries the stability watches' verdicts.
#include <cstdint>

#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// Installs the flag-setting handlers for SIGTERM and SIGINT in this process.
void install_stop_handlers();
// The signal received so far (0: none).
int stop_signal();

// What each program reports at every exchange step, as bits combined over both programs.
enum ExchangeFlag : int {
  kStopRequested = 1,   // a stop signal arrived: checkpoint and end with status 0
  kFluidUnstable = 2,   // the fluid's stability watch failed: end with kExitUnstable
  kBodiesUnstable = 4,  // the DEM's body watch failed: end with kExitUnstable
};

// The exchange steps at which both programs agree (stop requests, the fluid's and the bodies'
// watches): every fluid.stability.interval steps (the fluid watch's own cadence), at every
// checkpoint step, at every in-run rebalancing step (an overlapped fluid needs that step's
// states to place the bodies on its new blocks) and at the last step. Both programs compute it from
// the same scene and schedule. Agreeing at every step cost a reduction over both programs and a
// gather of every body state per step (+50 % wall time on
// configs/bench/cubes64_c100_particle_dt.yaml); a stop signal now acts within one interval (100
// steps by default).
bool agreement_at(const Scene& scene, const Schedule& schedule, std::int64_t step);

// Collective over MPI_COMM_WORLD: the bitwise or of `mine` over every rank of both programs,
// after exchange `step`. Waits like the exchanges do, under the same stall watch (World::stall,
// its limit scaled by the measured step time): throws SideError when the other program said
// goodbye (World::check_peer) or does not arrive within that limit, naming the step, so a rank
// stopped between an exchange and this reduction ends the job as the stall watchdog would.
int agree_flags(int mine, const World& world, std::int64_t step);

// The same as a barrier over both programs (e.g. both halves of a checkpoint are written).
inline void wait_for_both(const World& world, std::int64_t step) {
  agree_flags(0, world, step);
}

}  // namespace lbdem
