#pragma once
// Stopping a coupled run on request: SIGTERM or SIGINT (what batch schedulers send before the
// time limit) only sets a flag here; at the next exchange step both programs agree on it
// (one reduction over MPI_COMM_WORLD, which holds the ranks of both), write a checkpoint and
// end with status 0. A signal that reaches a single rank of either program is enough.
#include <functional>

#include "coupler_lib/coupling/wait.hpp"

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
// Collective over MPI_COMM_WORLD: the bitwise or of `mine` over every rank of both programs.
int agree_flags(int mine, WaitMode mode, const std::function<void()>& between_tests = {});

// Collective over MPI_COMM_WORLD (both programs): true when `mine` is true on any rank of
// either program. Waits like the exchanges do.
bool any_rank_of_both(bool mine, WaitMode mode, const std::function<void()>& between_tests = {});
// The same for "a stop signal arrived" (every exchange step).
inline bool agree_on_stop(WaitMode mode, const std::function<void()>& between_tests = {}) {
  return any_rank_of_both(stop_signal() != 0, mode, between_tests);
}

}  // namespace lbdem
