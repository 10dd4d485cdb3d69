#pragma once
// The DEM half of a checkpoint (docs/reliability.md, "Checkpoint and restart").
//
// It is the DEM journal up to the checkpoint's step: every body state the DEM sent and every
// load it received since step 0, one part per DEM rank with that rank's bodies
// (coupler_lib/coupling/journal.hpp: dem_half(prefix) with ".rank<k>" before ".h5"), and
// dem_half(prefix) itself with the checkpoint header and the length of the body trace, written
// once every part is complete. A restart rebuilds LAMMPS
// from the scene and replays those loads: the same deterministic integration on the same
// number of DEM ranks reproduces positions, quaternions, velocities, angular momenta, the
// contact history and every internal state of fix rigid/small bit for bit, each replayed
// state checked against the journal. LAMMPS's own restart files do not promise that for
// granular pair styles (their forces depend on half-step velocities) and lose the callback
// state of fix external; restoring bodies from their states alone would drop the contact
// history. The price: the replay costs the DEM's share of the run so far, and the journal
// grows by (128 + 72) B per body and step.
#include <mpi.h>

#include <string>

#include "coupler_lib/coupling/checkpoint_files.hpp"

namespace lbdem {

// Each rank copies its flushed part of the journal to its part of dem_half(prefix), then rank 0
// writes dem_half(prefix) with the header, each through a temporary name; collective over
// `side`.
void write_dem_checkpoint(const std::string& prefix, const std::string& journal,
                          const CheckpointHeader& header, long long trace_bytes, MPI_Comm side);

struct DemRestart {
  std::string path;  // dem_half(prefix)
  std::string part;  // this rank's part of the journal
  CheckpointHeader header;
  long long trace_bytes = -1;  // body trace length at the checkpoint (-1: no trace)
};

// Every rank reads the header of dem_half(prefix), checks it against `expected` and that its
// own part (DEM rank `rank`) exists; throws std::runtime_error naming the file and what to do.
DemRestart read_dem_checkpoint(const std::string& prefix, const CheckpointHeader& expected,
                               int rank);

}  // namespace lbdem
