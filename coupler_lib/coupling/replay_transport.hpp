#pragma once
// Replay transports: a recording (recording.hpp) stands in for the other program, so either
// program runs alone with --replay FILE.
//
// Fluid replay: the recorded states of each step are routed to the fluid ranks exactly as the
// DEM side would route them; the partial loads of all fluid ranks are summed per body in
// fluid-rank order (reduce_loads, as the DEM side does) and compared bit for bit with the
// recorded loads. DEM replay: the DEM side gets the recorded loads of the bodies it owns,
// and the states it sends are compared bit for bit with the recorded states. The first
// difference ends the run with its step, body, quantity and both values.
//
// Bit-for-bit agreement needs the same rank count and decomposition on the replayed side as
// in the recorded run (a different count changes summation order and LAMMPS's domain
// decomposition); the replay warns when they differ.
#include <mpi.h>

#include <memory>
#include <string>

#include "coupler_lib/coupling/recording.hpp"
#include "coupler_lib/coupling/side_info.hpp"
#include "coupler_lib/coupling/transport.hpp"

namespace lbdem {

// The recording, its parts (one per recorded DEM rank, recording.hpp) opened on rank 0 of this
// program, with its header on every rank.
class ReplaySource {
 public:
  // Collective over ctx.side_comm. Rank 0 throws when a part is missing, not a recording, or
  // was recorded from another scene.
  ReplaySource(const SideInfo& ctx, const std::string& path);
  ~ReplaySource();
  const RecordingInfo& info() const { return info_; }
  const std::string& path() const { return path_; }
  MPI_Comm side() const { return side_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Rank 0 only: every recorded state (reduced load) of `step`, merged from the parts, by id.
  std::vector<BodyState> states(std::int64_t step) const;
  std::vector<BodyLoad> loads(std::int64_t step) const;
  spdlog::logger& log() const { return *log_; }

 private:
  std::string path_;
  MPI_Comm side_;
  int rank_ = 0, size_ = 1;
  RecordingInfo info_;
  std::vector<std::unique_ptr<RecordingReader>> parts_;  // rank 0 only, by recorded DEM rank
  std::shared_ptr<spdlog::logger> log_;
};

class ReplayFluidTransport : public FluidTransport {
 public:
  ReplayFluidTransport(const SideInfo& ctx, const std::string& path);
  int dem_ranks() const override { return 1; }  // the recording acts as one DEM rank
  void announce(const FluidLayout& layout) override;
  std::vector<std::vector<BodyState>> receive_states(std::int64_t step) override;
  void send_loads(std::int64_t step,
                  const std::vector<std::vector<BodyLoad>>& per_dem_rank) override;

 private:
  ReplaySource source_;
  FluidLayout layout_;
  bool announced_ = false;      // the first announce compares the layout with the recorded one
  std::vector<BodyState> all_;  // every recorded state of the current step, by id
};

class ReplayDemTransport : public DemTransport {
 public:
  ReplayDemTransport(const SideInfo& ctx, const std::string& path);
  int fluid_ranks() const override { return 1; }  // the recording acts as one fluid rank
  FluidLayout receive_layout() override;
  void send_states(std::int64_t step, std::span<const BodyState> owned,
                   const std::vector<std::vector<BodyState>>& per_fluid_rank) override;
  std::vector<std::vector<BodyLoad>> receive_loads(std::int64_t step) override;

 private:
  ReplaySource source_;
  std::vector<std::int64_t> owned_;  // ids sent this step, in the order sent
};

}  // namespace lbdem
