#include "coupler_lib/coupling/recorder.hpp"

#include <algorithm>

#include "coupler_lib/output/gather.hpp"

namespace lbdem {

namespace {

template <class Packet>
std::vector<Packet> gather_sorted(std::span<const Packet> mine, MPI_Comm side) {
  std::vector<Packet> all;
  for (auto& part : gather_by_rank(mine, side)) all.insert(all.end(), part.begin(), part.end());
  std::sort(all.begin(), all.end(), [](const Packet& a, const Packet& b) { return a.id < b.id; });
  return all;
}

}  // namespace

Recorder::Recorder(MPI_Comm side, const std::string& path, const RecordingInfo& info)
    : side_(side) {
  MPI_Comm_rank(side_, &rank_);
  if (rank_ == 0) writer_ = std::make_unique<RecordingWriter>(path, info);
}

Recorder::~Recorder() = default;

void Recorder::states(std::int64_t step, std::span<const BodyState> owned) {
  const auto all = gather_sorted(owned, side_);
  if (writer_) writer_->append_states(step, all);
}

void Recorder::loads(std::int64_t step, std::span<const BodyLoad> reduced) {
  const auto all = gather_sorted(reduced, side_);
  if (!writer_) return;
  writer_->append_loads(step, all);
  // Flushed now and then, so a run that fails later leaves a readable recording up to here.
  if (++steps_ % kFlushEvery == 0) writer_->flush();
}

void Recorder::flush() {
  if (writer_) writer_->flush();
}

}  // namespace lbdem
