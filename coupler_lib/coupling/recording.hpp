#pragma once
// A recording: the packets that crossed between the programs, in HDF5 files of this layout.
// coupling.record (`run.h5`) and the checkpoint journal write one file per DEM rank
// (`run.rank<r>.h5`, journal_part in journal.hpp), each with the packets of that rank's bodies,
// so nothing per step passes through one rank; a replay merges the parts by body id.
//
// Layout of a file (written by one process; h5dump shows it as it is):
//   attributes  protocol_version, scene_hash, scene_file, fluid_ranks, dem_ranks
//   fluid_layout      the fluid decomposition at the start, as pack_layout() writes it
//   states            every BodyState the DEM rank sent, per step sorted by body id
//   loads             every reduced BodyLoad the DEM rank received, per step sorted by id
//   state_steps, load_steps   (step, offset, count) rows indexing the two tables
// The tables grow in chunks, so a run of any length is recorded without holding it in memory.
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/coupling/routing.hpp"

namespace lbdem {

struct RecordingInfo {
  std::uint32_t protocol = kProtocolVersion;
  std::uint64_t scene_hash = 0;
  std::string scene_file;
  int fluid_ranks = 0;
  int dem_ranks = 0;
  FluidLayout layout;
};

class RecordingWriter {
 public:
  // Creates (truncates) `path`. Throws std::runtime_error naming the file on failure.
  RecordingWriter(const std::string& path, const RecordingInfo& info);
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  void append_states(std::int64_t step, std::span<const BodyState> states);
  void append_loads(std::int64_t step, std::span<const BodyLoad> loads);
  void flush();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

class RecordingReader {
 public:
  // Throws std::runtime_error naming the file when it is missing or not a recording.
  explicit RecordingReader(const std::string& path);
  ~RecordingReader();
  RecordingReader(const RecordingReader&) = delete;
  RecordingReader& operator=(const RecordingReader&) = delete;

  const RecordingInfo& info() const;
  // Throw std::runtime_error when the step was not recorded.
  std::vector<BodyState> states(std::int64_t step) const;
  std::vector<BodyLoad> loads(std::int64_t step) const;
  std::vector<std::int64_t> state_steps() const;
  std::vector<std::int64_t> load_steps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lbdem
