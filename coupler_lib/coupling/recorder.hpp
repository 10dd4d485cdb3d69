#pragma once
// Records a live run on the DEM side (coupling.record): per step, the states the DEM ranks
// sent and the reduced loads they received, gathered on DEM rank 0 and sorted by body id.
// Those two lists are all either program needs to be replayed alone.
#include <mpi.h>

#include <memory>
#include <span>
#include <string>

#include "coupler_lib/coupling/recording.hpp"

namespace lbdem {

class Recorder {
 public:
  // Collective over `side`; rank 0 creates the file.
  Recorder(MPI_Comm side, const std::string& path, const RecordingInfo& info);
  ~Recorder();
  // Collective over `side`.
  void states(std::int64_t step, std::span<const BodyState> owned);
  void loads(std::int64_t step, std::span<const BodyLoad> reduced);
  // Everything appended so far on disk (rank 0; a no-op elsewhere).
  void flush();

 private:
  MPI_Comm side_;
  int rank_ = 0;
  static constexpr int kFlushEvery = 16;     // steps between flushes of the file
  std::unique_ptr<RecordingWriter> writer_;  // rank 0 only
  std::int64_t steps_ = 0;
};

}  // namespace lbdem
