#pragma once
// The common `main` of both binaries: MPI start-up, command line, scene loading, logging,
// and the fail-fast policy.
//
// Fail-fast, so that a coupled job never hangs and prints each message once:
// * command line and scene errors: every rank of both binaries agrees on the outcome
//   (one reduction over MPI_COMM_WORLD) before any coupling starts; the first failing rank
//   prints its message, every rank finalizes and exits 1;
// * JobError (thrown identically on every rank of both binaries, e.g. by the handshake):
//   world rank 0 prints it, every rank finalizes and exits 1;
// * SideError / SceneError thrown from `run` (every rank of one binary sees it): that
//   binary's rank 0 prints it and calls MPI_Abort on MPI_COMM_WORLD;
// * any other exception is local to a rank: that rank prints it and calls MPI_Abort on
//   MPI_COMM_WORLD, which ends both binaries within seconds. A process that exits without
//   MPI_Finalize (a crash) makes mpirun end the whole job as well.
#include <mpi.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "coupler_lib/app/command_line.hpp"
#include "coupler_lib/app/logging.hpp"
#include "coupler_lib/coupling/side_info.hpp"
#include "coupler_lib/errors.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

struct AppInfo {
  std::string side;         // "fluid" or "dem": the role in the coupling
  std::string program;      // executable name for messages
  std::string description;  // one line for --help
};

// The program's side of the world (ranks, names, scene hash, coupling keys) plus what only
// the programs themselves read: the command line and the whole scene.
struct AppContext : SideInfo {
  AppInfo info;
  CommandLine cli;
  Scene scene;
};

// `check` prints derived parameters for --check; `run` does the work. Both may throw.
int run_app(int argc, char** argv, const AppInfo& info,
            const std::function<void(AppContext&)>& check,
            const std::function<int(AppContext&)>& run);

}  // namespace lbdem
