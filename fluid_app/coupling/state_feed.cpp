#include "fluid_app/coupling/state_feed.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace lbdem {

void StateFeed::receive(std::int64_t step) {
  held_ = coupler_->receive_states(step);
  received_ = step;
  pending_ = true;
}

const std::vector<BodyState>& StateFeed::start(std::int64_t step) {
  receive(step);
  pending_ = false;
  return held_;
}

void StateFeed::send(std::int64_t step, std::span<const BodyLoad> loads) {
  if (!overlap_) {
    coupler_->send_loads(step, loads);
    return;
  }
  if (received_ < step - 1) receive(step - 1);
  // The loads are those of the bodies of an older receive; a body that has since left this
  // rank's reach can only be answered with a zero load (the coupler routes loads to the DEM
  // rank of the latest states).
  std::vector<BodyLoad> kept;
  kept.reserve(loads.size());
  for (const BodyLoad& l : loads) {
    const auto it = std::lower_bound(held_.begin(), held_.end(), l.id,
                                     [](const BodyState& s, std::int64_t id) { return s.id < id; });
    if (it != held_.end() && it->id == l.id) {
      kept.push_back(l);
      continue;
    }
    const bool zero =
        std::all_of(std::begin(l.f), std::end(l.f), [](double v) { return v == 0; }) &&
        std::all_of(std::begin(l.t), std::end(l.t), [](double v) { return v == 0; });
    if (!zero)
      throw std::runtime_error("body " + std::to_string(l.id) + " left the reach of this fluid " +
                               "rank while it still covered cells there (coupling.overlap runs "
                               "the fluid one step behind the DEM): raise coupling.margin");
  }
  coupler_->send_loads(step, kept);
}

const std::vector<BodyState>& StateFeed::next(std::int64_t step, bool sync) {
  if (!overlap_ || sync) receive(step);
  fresh_ = pending_;
  pending_ = false;
  return held_;
}

void StateFeed::finish(std::int64_t step) {
  while (received_ < step) receive(received_ + 1);
}

}  // namespace lbdem
