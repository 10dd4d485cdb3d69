#include "coupler_lib/coupling/stop_request.hpp"

#include <mpi.h>

#include <csignal>

#include "coupler_lib/coupling/stall_watch.hpp"

namespace lbdem {

namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_stop_signal(int sig) {
  g_signal = sig;
}

}  // namespace

void install_stop_handlers() {
  std::signal(SIGTERM, on_stop_signal);
  std::signal(SIGINT, on_stop_signal);
}

int stop_signal() {
  return static_cast<int>(g_signal);
}

bool agreement_at(const Scene& scene, const Schedule& schedule, std::int64_t step) {
  const long interval = scene.fluid ? scene.fluid->output.stability.interval : 0;
  return (interval > 0 && step % interval == 0) || schedule.checkpoint_at(step) ||
         schedule.rebalance_at(step) || step == schedule.steps;
}

int agree_flags(int mine, const World& world, std::int64_t step) {
  int all = 0;
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Iallreduce(&mine, &all, 1, MPI_INT, MPI_BOR, MPI_COMM_WORLD, &req);
  // The same watch as the exchanges: the other program may be running its stability check
  // (a pass over the lattice) or writing a checkpoint before it joins.
  StallWatch& stall = world.stall();
  stall.begin(step, StallWatch::Wait::agreement);
  wait_request(req, world.wait(), [&] {
    world.check_peer();
    stall.check();
  });
  stall.end();
  return all;
}

}  // namespace lbdem
