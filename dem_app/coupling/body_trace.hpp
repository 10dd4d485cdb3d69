#pragma once
// Per-body time series of a coupled run (CSV, rank 0 writes): time, id, centre of mass,
// velocity, angular velocity, orientation and the hydrodynamic force and torque that acted
// on the body during the last fluid step. This is what the validation checkers read.
#include <mpi.h>

#include <fstream>
#include <span>
#include <string>

#include "coupler_lib/coupling/packets.hpp"

namespace lbdem {

class BodyTrace {
 public:
  // `resume_bytes` >= 0: continue a restarted run's trace, cut back to that length.
  BodyTrace(const std::string& path, MPI_Comm comm, long long resume_bytes = -1);
  // Bytes written so far, on disk (rank 0; 0 elsewhere): what a checkpoint stores.
  long long flushed_bytes();
  // Collective: `states` and `loads` are this rank's owned bodies (loads may be empty at the
  // first row); rank 0 gathers them in pieces of kOutputChunk ids
  // (dem_app/output/output_chunks.hpp) and writes one row per body, sorted by id.
  void write(double time, std::span<const BodyState> states, std::span<const BodyLoad> loads);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  MPI_Comm comm_;
  int rank_ = 0;
  std::ofstream out_;
};

}  // namespace lbdem
