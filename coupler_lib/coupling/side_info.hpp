#pragma once
// What the coupling layer knows about the program it runs in: the ranks of this program, its
// place in the MPMD launch, its names, the scene it read and the scene's `coupling:` keys.
// The common main fills it (AppContext extends it), so a program passes its context wherever
// a SideInfo is wanted; tests and tools can fill one by hand.
#include <mpi.h>
#include <spdlog/spdlog.h>

#include <cstdint>
#include <memory>
#include <string>

#include "coupler_lib/scene/coupling_section.hpp"

namespace lbdem {

struct SideInfo {
  std::string side;                    // "fluid" or "dem": the role in the coupling
  std::string program;                 // executable name for messages
  std::string scene_file;              // the scene path as given on the command line
  std::uint64_t scene_hash = 0;        // Scene::hash: both programs must have read the same bytes
  CouplingParams coupling;             // the scene's `coupling:` keys
  MPI_Comm side_comm = MPI_COMM_NULL;  // the ranks of this binary
  int rank = 0;                        // rank within side_comm
  int size = 1;
  int world_rank = 0;
  int app = 0;        // this binary's index in the MPMD launch (MPI_APPNUM)
  int app_count = 1;  // number of applications in the MPMD launch
  std::shared_ptr<spdlog::logger> log;
};

}  // namespace lbdem
