#pragma once
// A recording: every packet that crossed between the programs, in one HDF5 file.
//
// Layout of the file (all written by one process; h5dump shows it as it is):
//   attributes  protocol_version, scene_hash, scene_file, fluid_ranks, dem_ranks
//   fluid_layout      the fluid decomposition as pack_layout() writes it
//   states            every BodyState the DEM side sent, per step sorted by body id
//   loads             every reduced BodyLoad the DEM side received, per step sorted by id
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
