#include "coupler_lib/coupling/replay_transport.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "coupler_lib/coupling/compare.hpp"
#include "coupler_lib/coupling/reduce.hpp"
#include "coupler_lib/errors.hpp"
#include "coupler_lib/output/gather.hpp"

namespace lbdem {

namespace {

std::string hex(std::uint64_t v) {
  char b[32];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(v));
  return b;
}

template <class Packet>
std::vector<Packet> flatten(const std::vector<std::vector<Packet>>& parts) {
  std::vector<Packet> all;
  for (const auto& p : parts) all.insert(all.end(), p.begin(), p.end());
  return all;
}

}  // namespace

ReplaySource::ReplaySource(const SideInfo& ctx, const std::string& path)
    : path_(path), side_(ctx.side_comm), rank_(ctx.rank), size_(ctx.size), log_(ctx.log) {
  // Only rank 0 touches the file; an error there ends the job with one message while the
  // other ranks wait in the broadcast below.
  std::vector<double> layout;
  std::vector<char> scene_file;
  std::vector<std::uint64_t> header(4);
  if (rank_ == 0) {
    reader_ = std::make_unique<RecordingReader>(path);
    const RecordingInfo& in = reader_->info();
    if (in.scene_hash != ctx.scene_hash)
      throw std::runtime_error(path + " was recorded from scene '" + in.scene_file + "' (hash " +
                               hex(in.scene_hash) + "), but this run reads '" + ctx.scene_file +
                               "' (hash " + hex(ctx.scene_hash) +
                               "); replay with the scene file of the recorded run");
    header = {in.protocol, in.scene_hash, static_cast<std::uint64_t>(in.fluid_ranks),
              static_cast<std::uint64_t>(in.dem_ranks)};
    layout = pack_layout(in.layout);
    scene_file.assign(in.scene_file.begin(), in.scene_file.end());
  }
  broadcast(header, 0, side_);
  broadcast(layout, 0, side_);
  broadcast(scene_file, 0, side_);
  info_.protocol = static_cast<std::uint32_t>(header[0]);
  info_.scene_hash = header[1];
  info_.fluid_ranks = static_cast<int>(header[2]);
  info_.dem_ranks = static_cast<int>(header[3]);
  info_.layout = unpack_layout(layout);
  info_.scene_file.assign(scene_file.begin(), scene_file.end());
  if (rank_ == 0)
    log_->info("replaying {} (recorded with {} fluid : {} DEM ranks)", path_, info_.fluid_ranks,
               info_.dem_ranks);
}

ReplaySource::~ReplaySource() = default;

ReplayFluidTransport::ReplayFluidTransport(const SideInfo& ctx, const std::string& path)
    : source_(ctx, path) {}

void ReplayFluidTransport::announce(const FluidLayout& layout) {
  layout_ = layout;
  if (source_.rank() == 0 && pack_layout(layout) != pack_layout(source_.info().layout))
    source_.log().warn(
        "this fluid decomposition ({} ranks) differs from the recorded one ({} ranks): "
        "loads will not match the recording bit for bit",
        layout.boxes.size(), source_.info().layout.boxes.size());
}

std::vector<std::vector<BodyState>> ReplayFluidTransport::receive_states(std::int64_t step) {
  if (source_.rank() == 0) all_ = source_.reader()->states(step);
  broadcast(all_, 0, source_.side());
  // Route exactly as the DEM side does (dem_coupler.cpp).
  std::vector<BodyState> mine;
  for (const BodyState& s : all_) {
    const auto ranks = touched_ranks(layout_, s.x, layout_.reach(s.shape));
    if (std::binary_search(ranks.begin(), ranks.end(), source_.rank())) mine.push_back(s);
  }
  return {mine};
}

void ReplayFluidTransport::send_loads(std::int64_t step,
                                      const std::vector<std::vector<BodyLoad>>& per_dem_rank) {
  const std::vector<BodyLoad> mine = flatten(per_dem_rank);
  const auto per_fluid_rank = gather_by_rank<BodyLoad>(mine, source_.side());
  if (source_.rank() != 0) return;
  const std::vector<BodyLoad> reduced = reduce_loads(all_, per_fluid_rank, step);
  const std::vector<BodyLoad> recorded = source_.reader()->loads(step);
  if (auto diff = first_mismatch(step, recorded, reduced))
    throw std::runtime_error("fluid replay of " + source_.path() +
                             ": the loads differ from the recording at " + *diff);
}

ReplayDemTransport::ReplayDemTransport(const SideInfo& ctx, const std::string& path)
    : source_(ctx, path) {
  if (source_.rank() == 0 && source_.info().dem_ranks != source_.size())
    source_.log().warn(
        "replaying with {} DEM ranks, recorded with {}: states may not match bit for bit",
        source_.size(), source_.info().dem_ranks);
}

FluidLayout ReplayDemTransport::receive_layout() {
  return source_.info().layout;
}

void ReplayDemTransport::send_states(std::int64_t step, std::span<const BodyState> owned,
                                     const std::vector<std::vector<BodyState>>&) {
  owned_.clear();
  for (const BodyState& s : owned) owned_.push_back(s.id);
  std::vector<BodyState> all = flatten(gather_by_rank(owned, source_.side()));
  if (source_.rank() != 0) return;
  std::sort(all.begin(), all.end(),
            [](const BodyState& a, const BodyState& b) { return a.id < b.id; });
  const std::vector<BodyState> recorded = source_.reader()->states(step);
  if (auto diff = first_mismatch(step, recorded, all))
    throw std::runtime_error("DEM replay of " + source_.path() +
                             ": the states differ from the recording at " + *diff);
}

std::vector<std::vector<BodyLoad>> ReplayDemTransport::receive_loads(std::int64_t step) {
  std::vector<BodyLoad> all;
  if (source_.rank() == 0) all = source_.reader()->loads(step);
  broadcast(all, 0, source_.side());
  return {loads_of(owned_, all, source_.path(), step)};
}

}  // namespace lbdem
