#include "coupler_lib/coupling/stop_request.hpp"

#include <mpi.h>

#include <csignal>

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

int agree_flags(int mine, WaitMode mode, const std::function<void()>& between_tests) {
  int all = 0;
  MPI_Request req = MPI_REQUEST_NULL;
  MPI_Iallreduce(&mine, &all, 1, MPI_INT, MPI_BOR, MPI_COMM_WORLD, &req);
  wait_request(req, mode, between_tests);
  return all;
}

bool any_rank_of_both(bool flag, WaitMode mode, const std::function<void()>& between_tests) {
  return agree_flags(flag ? 1 : 0, mode, between_tests) != 0;
}

}  // namespace lbdem
