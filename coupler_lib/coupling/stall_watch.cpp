#include "coupler_lib/coupling/stall_watch.hpp"

#include "coupler_lib/coupling/checkpoint_files.hpp"

#include <algorithm>
#include <sstream>

#include "coupler_lib/errors.hpp"

namespace lbdem {

StallWatch::StallWatch(double timeout_s, const PeerInfo& peer)
    : timeout_s_(timeout_s), peer_(peer.program + " (the " + peer.side + " side)") {}

void StallWatch::begin(std::int64_t step) {
  step_ = step;
  wait_start_ = Clock::now();
}

void StallWatch::end() {
  const auto now = Clock::now();
  if (last_completed_ >= 0)
    slowest_gap_s_ =
        std::max(slowest_gap_s_, std::chrono::duration<double>(now - last_end_).count());
  last_end_ = now;
  last_completed_ = step_;
}

double StallWatch::limit_s() const {
  if (timeout_s_ > 0) return timeout_s_;
  return std::max(kAutomaticFloor, kAutomaticFactor * slowest_gap_s_);
}

void StallWatch::check() const {
  const double waited = std::chrono::duration<double>(Clock::now() - wait_start_).count();
  const double limit = limit_s();
  if (waited <= limit) return;
  std::ostringstream m;
  m.precision(3);
  m << peer_ << " has sent nothing for " << waited << " s (limit " << limit << " s, "
    << (timeout_s_ > 0 ? "coupling.stall_timeout" : "automatic: coupling.stall_timeout not set")
    << ") while this program waits for its packets at step " << step_
    << ": one of its ranks is stopped, hung or deadlocked; this program's last completed exchange: "
    << (last_completed_ >= 0 ? "step " + std::to_string(last_completed_) : std::string("none"))
    << "; last checkpoint: "
    << (remembered_checkpoint().empty() ? std::string("none")
                                        : remembered_checkpoint() + " (continue with --restart " +
                                              remembered_checkpoint() + " on both programs)");
  throw SideError(m.str());
}

}  // namespace lbdem
