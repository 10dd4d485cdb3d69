#include "coupler_lib/coupling/stop_request.hpp"

#include <mpi.h>

#include <chrono>
#include <csignal>
#include <sstream>

#include "coupler_lib/coupling/checkpoint_files.hpp"
#include "coupler_lib/coupling/stall_watch.hpp"
#include "coupler_lib/errors.hpp"

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
         step == schedule.steps;
}

int agree_flags(int mine, const World& world, std::int64_t step) {
  int all = 0;
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Iallreduce(&mine, &all, 1, MPI_INT, MPI_BOR, MPI_COMM_WORLD, &req);
  const double limit =
      world.stall_timeout() > 0 ? world.stall_timeout() : StallWatch::kAutomaticFloor;
  const auto start = std::chrono::steady_clock::now();
  wait_request(req, world.wait(), [&] {
    world.check_peer();
    const double waited =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (waited <= limit) return;
    std::ostringstream m;
    m << world.peer().program << " (the " << world.peer().side << " side) has not joined the "
      << "agreement after exchange step " << step << " for " << waited << " s (limit " << limit
      << " s, coupling.stall_timeout): one of its ranks is stopped, hung or deadlocked; last "
      << "checkpoint: "
      << (remembered_checkpoint().empty() ? std::string("none") : remembered_checkpoint());
    throw SideError(m.str());
  });
  return all;
}

}  // namespace lbdem
