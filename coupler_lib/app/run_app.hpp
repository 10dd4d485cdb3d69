#pragma once
// The common `main` of both binaries: MPI start-up, command line, scene loading, logging,
// and the fail-fast policy.
//
// Fail-fast: a bad scene is detected identically on every rank of both binaries (they share
// the parser), so every rank returns 1 after a collective MPI_Finalize and the message is
// printed once (by world rank 0). Any other error is local to a rank: that rank prints it
// and calls MPI_Abort on MPI_COMM_WORLD, which ends both binaries within seconds.
#include <mpi.h>

#include <functional>
#include <memory>
#include <string>

#include "coupler_lib/app/command_line.hpp"
#include "coupler_lib/app/logging.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

struct AppInfo {
  std::string side;         // "fluid" or "dem": the role in the coupling
  std::string program;      // executable name for messages
  std::string description;  // one line for --help
};

struct AppContext {
  AppInfo info;
  CommandLine cli;
  Scene scene;
  MPI_Comm side_comm = MPI_COMM_NULL;  // the ranks of this binary
  int rank = 0;                        // rank within side_comm
  int size = 1;
  int world_rank = 0;
  int app_count = 1;  // number of applications in the MPMD launch
  std::shared_ptr<spdlog::logger> log;
};

// `check` prints derived parameters for --check; `run` does the work. Both may throw.
int run_app(int argc, char** argv, const AppInfo& info,
            const std::function<void(AppContext&)>& check,
            const std::function<int(AppContext&)>& run);

}  // namespace lbdem
