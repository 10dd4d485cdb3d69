#pragma once
// The DEM half of a checkpoint (docs/reliability.md, "Checkpoint and restart").
//
// It is the DEM journal up to the checkpoint's step: every body state the DEM sent and every
// load it received since step 0 (the recording format, coupler_lib/coupling/recording.hpp),
// plus the checkpoint header and the length of the body trace. A restart rebuilds LAMMPS
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

// Rank 0 copies the flushed journal to dem_half(prefix) through a temporary name and adds
// the header; collective over `side`.
void write_dem_checkpoint(const std::string& prefix, const std::string& journal,
                          const CheckpointHeader& header, long long trace_bytes, MPI_Comm side);

struct DemRestart {
  std::string path;  // dem_half(prefix)
  CheckpointHeader header;
  long long trace_bytes = -1;  // body trace length at the checkpoint (-1: no trace)
};

// Every rank reads the header of dem_half(prefix) and checks it against `expected`; throws
// std::runtime_error naming the file and what to do.
DemRestart read_dem_checkpoint(const std::string& prefix, const CheckpointHeader& expected);

}  // namespace lbdem
