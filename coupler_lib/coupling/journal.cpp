#include "coupler_lib/coupling/journal.hpp"

#include <algorithm>
#include <stdexcept>

#include "coupler_lib/coupling/compare.hpp"

namespace lbdem {

namespace {

template <class Packet>
std::vector<Packet> sorted_by_id(std::span<const Packet> packets) {
  std::vector<Packet> s(packets.begin(), packets.end());
  std::sort(s.begin(), s.end(), [](const Packet& a, const Packet& b) { return a.id < b.id; });
  return s;
}

}  // namespace

std::string journal_part(const std::string& path, int rank) {
  const std::string ext = ".h5";
  const bool h5 = path.size() >= ext.size() && path.compare(path.size() - 3, 3, ext) == 0;
  return (h5 ? path.substr(0, path.size() - 3) : path) + ".rank" + std::to_string(rank) + ext;
}

JournalWriter::JournalWriter(const std::string& path, const RecordingInfo& info)
    : path_(path), writer_(path, info) {}

void JournalWriter::states(std::int64_t step, std::span<const BodyState> owned) {
  writer_.append_states(step, sorted_by_id(owned));
}

void JournalWriter::loads(std::int64_t step, std::span<const BodyLoad> reduced) {
  writer_.append_loads(step, sorted_by_id(reduced));
  if (++steps_ % kFlushEvery == 0) writer_.flush();
}

void JournalWriter::flush() {
  writer_.flush();
}

JournalDemTransport::JournalDemTransport(const SideInfo& ctx, const std::string& part)
    : path_(part), reader_(part) {
  if (reader_.info().scene_hash != ctx.scene_hash)
    throw std::runtime_error(part + " was journalled for another scene (" +
                             reader_.info().scene_file +
                             "): restart with the scene of the checkpointed run");
}

void JournalDemTransport::send_states(std::int64_t step, std::span<const BodyState> owned,
                                      const std::vector<std::vector<BodyState>>&) {
  owned_.clear();
  for (const BodyState& s : owned) owned_.push_back(s.id);
  const std::vector<BodyState> recorded = reader_.states(step);
  if (auto diff = first_mismatch(step, recorded, sorted_by_id(owned)))
    throw std::runtime_error("restart replay of " + path_ +
                             ": the states differ from the journal at " + *diff);
}

std::vector<std::vector<BodyLoad>> JournalDemTransport::receive_loads(std::int64_t step) {
  return {loads_of(owned_, reader_.loads(step), path_, step)};
}

}  // namespace lbdem
