#include "coupler_lib/coupling/dem_coupler.hpp"

#include <stdexcept>
#include <string>
#include <unordered_set>

#include "coupler_lib/coupling/live_transport.hpp"
#include "coupler_lib/coupling/reduce.hpp"
#include "coupler_lib/coupling/replay_transport.hpp"
#include "coupler_lib/errors.hpp"
#include "coupler_lib/scene/scene_fingerprint.hpp"

namespace lbdem {

DemCoupler::DemCoupler(const World& world, const Scene& scene, const std::string& journal)
    : DemCoupler(world.side(), std::make_unique<LiveDemTransport>(world)) {
  RecordingInfo info;
  info.scene_hash = scene.hash;
  info.scene_file = scene.file;
  info.fluid_ranks = world.peer().size;
  info.dem_ranks = world.size();
  info.layout = layout_;
  if (!scene.coupling.record.empty())
    recorder_ =
        std::make_unique<JournalWriter>(journal_part(scene.coupling.record, world.rank()), info);
  if (!journal.empty()) {
    // The journal outlives edits of time.end and outputs: it is identified by the scene
    // fingerprint, which a restart checks, instead of the bytes of the file.
    info.scene_hash = scene_fingerprint(scene);
    journal_ = std::make_unique<JournalWriter>(journal_part(journal, world.rank()), info);
  }
}

DemCoupler::DemCoupler(const SideInfo& ctx, const std::string& recording)
    : DemCoupler(ctx.side_comm, std::make_unique<ReplayDemTransport>(ctx, recording)) {}

std::unique_ptr<DemCoupler> DemCoupler::replaying_journal(const SideInfo& ctx,
                                                          const std::string& part) {
  return std::unique_ptr<DemCoupler>(
      new DemCoupler(ctx.side_comm, std::make_unique<JournalDemTransport>(ctx, part)));
}

DemCoupler::DemCoupler(MPI_Comm side, std::unique_ptr<DemTransport> transport)
    : transport_(std::move(transport)), side_(side) {
  layout_ = transport_->receive_layout();
  try {
    validate_layout(layout_);
  } catch (const std::invalid_argument& e) {
    throw SideError(std::string("fluid decomposition received by the DEM side: ") + e.what());
  }
}

DemCoupler::~DemCoupler() = default;

void DemCoupler::send_states(std::int64_t step, std::span<const BodyState> owned) {
  const ScopedCouplingTimer timer(times_);
  sent_.assign(owned.begin(), owned.end());
  std::unordered_set<std::int64_t> ids;
  for (BodyState& s : sent_) {
    s.version = kProtocolVersion;
    s.step = step;
    if (!ids.insert(s.id).second)
      throw std::runtime_error("send_states at step " + std::to_string(step) + ": body " +
                               std::to_string(s.id) + " appears twice in the owned list");
    if (s.shape < 0 || s.shape >= static_cast<int>(layout_.shape_radius.size()))
      throw std::runtime_error("body " + std::to_string(s.id) + " has shape index " +
                               std::to_string(s.shape) + ", but the fluid side knows " +
                               std::to_string(layout_.shape_radius.size()) + " shapes");
  }
  // Routed by the announced (or recorded) layout; a replay checks `sent_` itself.
  const auto buckets = route(sent_);
  count_traffic(times_, buckets);
  transport_->send_states(step, sent_, buckets);
  if (recorder_) recorder_->states(step, sent_);
  if (journal_) journal_->states(step, sent_);
  step_ = step;
  answered_ = false;
}

std::vector<std::vector<BodyState>> DemCoupler::route(std::span<const BodyState> states) const {
  std::vector<std::vector<BodyState>> buckets(layout_.boxes.size());
  for (const BodyState& s : states)
    for (int r : touched_ranks(layout_, s.x, layout_.reach(s.shape)))
      buckets[static_cast<size_t>(r)].push_back(s);
  return buckets;
}

bool DemCoupler::follow_layout() {
  const ScopedCouplingTimer timer(times_);
  FluidLayout next = transport_->receive_layout();
  try {
    validate_layout(next);
  } catch (const std::invalid_argument& e) {
    throw SideError(std::string("fluid decomposition received by the DEM side: ") + e.what());
  }
  if (pack_layout(next) == pack_layout(layout_)) return false;
  layout_ = std::move(next);
  const auto buckets = route(sent_);
  count_traffic(times_, buckets);
  transport_->send_states(step_, sent_, buckets);
  return true;
}

std::vector<BodyLoad> DemCoupler::receive_loads(std::int64_t step) {
  const ScopedCouplingTimer timer(times_);
  if (answered_)
    throw std::runtime_error("receive_loads(" + std::to_string(step) +
                             ") without a send_states before it: each send_states is answered "
                             "by exactly one receive_loads (last sent: step " +
                             std::to_string(step_) + ")");
  answered_ = true;
  const auto partials = transport_->receive_loads(step);
  count_traffic(times_, partials);
  std::vector<BodyLoad> loads = reduce_loads(sent_, partials, step);
  if (recorder_) recorder_->loads(step, loads);
  if (journal_) journal_->loads(step, loads);
  return loads;
}

void DemCoupler::journal_states(std::int64_t step, std::span<const BodyState> owned) {
  if (!journal_) return;
  std::vector<BodyState> s(owned.begin(), owned.end());
  for (BodyState& b : s) {
    b.version = kProtocolVersion;
    b.step = step;
  }
  journal_->states(step, s);
}

void DemCoupler::journal_loads(std::int64_t step, std::span<const BodyLoad> loads) {
  if (journal_) journal_->loads(step, loads);
}

std::string DemCoupler::flush_journal() {
  if (!journal_) return {};
  journal_->flush();
  return journal_->path();
}

CouplingTimes DemCoupler::times() const {
  CouplingTimes t = times_;
  t.idle_s = transport_->waited();
  return t;
}

}  // namespace lbdem
