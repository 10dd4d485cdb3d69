#pragma once
// Waiting for an MPI request without burning the core the other program needs.
//
// Open MPI's blocking calls (MPI_Wait, MPI_Barrier, ...) busy-poll: a fluid rank waiting for
// the DEM would spin at 100 % on the very core the DEM rank computes on when both share a
// node. `backoff` instead tests the request without sleeping for 200 us (a message already on
// its way costs no sleep), then sleeps between tests, starting at 50 us and doubling up to
// 0.5 ms, so an idle side costs about 2 % of a core and a message is noticed at most ~0.5 ms
// late (docs/performance.md, "Waiting without burning a core").
// `blocking` is the plain MPI_Wait, kept for comparison (tools/coupler_idle_bench measures both).
#include <mpi.h>

#include <chrono>
#include <functional>
#include <string>

#include "coupler_lib/scene/choices.hpp"

namespace lbdem {

// Completes `request` (it becomes MPI_REQUEST_NULL). `between_tests`, if given, runs between
// two tests and may throw to give up (World::check_peer); blocking mode then spins on
// MPI_Test instead of calling MPI_Wait.
void wait_request(MPI_Request& request, WaitMode mode,
                  const std::function<void()>& between_tests = {});

// Waits with back-off until `request` completes (true) or `deadline` passes (false; the
// request stays pending).
bool wait_request_until(MPI_Request& request, std::chrono::steady_clock::time_point deadline);

}  // namespace lbdem
