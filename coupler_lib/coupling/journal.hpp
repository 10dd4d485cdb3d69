#pragma once
// The DEM journal of a live run, one part per DEM rank: every state this rank sent and every
// reduced load it received, per exchange step, sorted by body id, in the recording format
// (recording.hpp). A checkpoint keeps a copy of each part up to its step, and a restart on the
// same DEM rank count (which LAMMPS needs to reproduce its run bit for bit) replays on every
// rank its own part: nothing per step passes through one rank, each rank writes and reads only
// its own bodies (docs/reliability.md, "Checkpoint and restart"; docs/scaling.md).
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "coupler_lib/coupling/recording.hpp"
#include "coupler_lib/coupling/side_info.hpp"
#include "coupler_lib/coupling/transport.hpp"

namespace lbdem {

// The part of DEM rank `rank` of the journal or checkpoint file `path` ("x.h5" ->
// "x.rank<rank>.h5").
std::string journal_part(const std::string& path, int rank);

// Appends this rank's exchanges to its part (no communication).
class JournalWriter {
 public:
  // Creates (truncates) `path`; throws std::runtime_error naming it on failure.
  JournalWriter(const std::string& path, const RecordingInfo& info);
  void states(std::int64_t step, std::span<const BodyState> owned);
  void loads(std::int64_t step, std::span<const BodyLoad> reduced);
  void flush();  // everything appended so far on disk
  const std::string& path() const { return path_; }

 private:
  static constexpr int kFlushEvery = 16;  // steps between flushes, so a failed run leaves
                                          // a readable part up to there
  std::string path_;
  RecordingWriter writer_;
  std::int64_t steps_ = 0;
};

// A restart's replay of this rank's part: the DEM gets the journalled loads of its bodies, and
// each state it sends is compared with the journal bit for bit (the first difference throws
// with its step, body and quantity). No communication.
class JournalDemTransport : public DemTransport {
 public:
  // Throws std::runtime_error when the part is missing, not a recording, or was written for
  // another scene fingerprint than ctx.scene_hash.
  JournalDemTransport(const SideInfo& ctx, const std::string& part);
  int fluid_ranks() const override { return reader_.info().fluid_ranks; }
  FluidLayout receive_layout() override { return reader_.info().layout; }
  void send_states(std::int64_t step, std::span<const BodyState> owned,
                   const std::vector<std::vector<BodyState>>& per_fluid_rank) override;
  std::vector<std::vector<BodyLoad>> receive_loads(std::int64_t step) override;

 private:
  std::string path_;
  RecordingReader reader_;
  std::vector<std::int64_t> owned_;  // ids of the last send_states, in its order
};

}  // namespace lbdem
