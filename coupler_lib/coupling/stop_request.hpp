#pragma once
// Stopping a coupled run on request: SIGTERM or SIGINT (what batch schedulers send before the
// time limit) only sets a flag here; at the next exchange step both programs agree on it
// (one reduction over MPI_COMM_WORLD, which holds the ranks of both), write a checkpoint and
// end with status 0. A signal that reaches a single rank of either program is enough. The same
// reduction carries the stability watches' verdicts.
#include <cstdint>

#include "coupler_lib/coupling/world.hpp"

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

// Collective over MPI_COMM_WORLD: the bitwise or of `mine` over every rank of both programs,
// after exchange `step`. Waits like the exchanges do; throws SideError when the other program
// said goodbye (World::check_peer) or does not arrive within coupling.stall_timeout (600 s when
// automatic), naming the step, so a rank stopped between an exchange and this reduction ends
// the job as the stall watchdog would.
int agree_flags(int mine, const World& world, std::int64_t step);

// The same as a barrier over both programs (e.g. both halves of a checkpoint are written).
inline void wait_for_both(const World& world, std::int64_t step) {
  agree_flags(0, world, step);
}

}  // namespace lbdem
