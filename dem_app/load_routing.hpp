#pragma once
// The DEM ranks' load exchange before each run, sparse: a load goes to its body's home rank
// (dem_app/load_table.hpp), and each rank fetches from the homes only the bodies of its own
// spheres. Per rank and run: one MPI_Alltoall of message sizes per phase (P integers) and
// point-to-point messages whose total size follows the loads set here and the bodies held
// here, never the total number of bodies.
#include <mpi.h>

#include <cstdint>
#include <vector>

#include "dem_app/external_load.hpp"
#include "dem_app/load_table.hpp"

namespace lbdem {

// Received by one rank from the others (payload and message sizes), summed over runs.
struct LoadTraffic {
  long long bytes = 0;
  long long messages = 0;
  long long exchanges = 0;
};

// Collective over comm: every rank's `pending` updates (applied at their homes in rank
// order, then in the order given, so the last one set wins reproducibly).
void deliver_loads(const std::vector<LoadUpdate>& pending, LoadTable& table, MPI_Comm comm,
                   LoadTraffic& traffic);

// Collective over comm: what the current run applies to each of `bodies` (sorted, unique),
// asked from their homes.
std::vector<AppliedLoad> fetch_loads(const std::vector<std::int64_t>& bodies,
                                     const LoadTable& table, bool kick, MPI_Comm comm,
                                     LoadTraffic& traffic);

}  // namespace lbdem
