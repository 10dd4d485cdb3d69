#pragma once
// The DEM ranks' load exchange before each run, sparse: a load goes to its body's home rank
// (dem_app/load_table.hpp), and each rank asks the homes only for the bodies of its own
// spheres. Per rank and run: one MPI_Alltoall of message sizes (P integers), then
// point-to-point messages (updates and questions to the homes, answers back) whose size
// follows the loads set on this rank and the bodies held here, never the total number of
// bodies.
#include <mpi.h>

#include <cstdint>
#include <vector>

#include "dem_app/external_load.hpp"
#include "dem_app/load_table.hpp"

namespace lbdem {

// Received by one rank from the others (payload and message sizes), summed over exchanges.
struct LoadTraffic {
  long long bytes = 0;
  long long messages = 0;
  long long exchanges = 0;
};

// What the homes do between taking the updates and answering: start the next run (the
// answers are its loads; kick: it has a first-evaluation correction) or not (the engine's
// set-up, whose force evaluation applies the current loads).
struct LoadRun {
  bool begin = false;
  bool kick = false;
};

// Collective over comm. Every rank's `pending` updates are applied at their homes in rank
// order, then in the order given (the last one set wins, reproducibly); returns what the run
// applies to each of `bodies` (sorted, unique; may be empty).
std::vector<AppliedLoad> exchange_loads(const std::vector<LoadUpdate>& pending,
                                        const std::vector<std::int64_t>& bodies, LoadTable& table,
                                        LoadRun run, MPI_Comm comm, LoadTraffic& traffic);

}  // namespace lbdem
