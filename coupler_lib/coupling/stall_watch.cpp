#include "coupler_lib/coupling/stall_watch.hpp"

#include <algorithm>
#include <sstream>

#include "coupler_lib/coupling/checkpoint_files.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/errors.hpp"

namespace lbdem {

bool PauseSteps::at(std::int64_t step) const {
  if (step <= 0) return false;
  return (checkpoint_every > 0 && step % checkpoint_every == 0) ||
         (fields_every > 0 && step % fields_every == 0);
}

PauseSteps pause_steps(const Scene& scene, const Schedule& schedule) {
  PauseSteps p;
  p.checkpoint_every = schedule.checkpoint_interval;
  if (scene.fluid && scene.fluid->output.fields) p.fields_every = scene.fluid->output.fields->every;
  return p;
}

StallWatch::StallWatch(double timeout_s, const PeerInfo& peer)
    : timeout_s_(timeout_s), peer_(peer.program + " (the " + peer.side + " side)") {}

void StallWatch::begin(std::int64_t step, Wait kind) {
  step_ = step;
  kind_ = kind;
  wait_start_ = Clock::now();
}

void StallWatch::end() {
  const auto now = Clock::now();
  // The set-up's gaps and the announced pauses are not steps: they would lift the limit of
  // the whole run.
  if (completed_ >= kSetUpWaits && !pauses_.held_by(step_))
    slowest_gap_s_ =
        std::max(slowest_gap_s_, std::chrono::duration<double>(now - last_end_).count());
  last_end_ = now;
  last_completed_ = step_;
  if (kind_ == Wait::packets) ++completed_;
}

double StallWatch::limit_s() const {
  if (timeout_s_ > 0) return timeout_s_;
  if (completed_ < kSetUpWaits) return kSetUpLimit;
  const double stepping = std::max(kAutomaticFloor, kAutomaticFactor * slowest_gap_s_);
  return pauses_.held_by(step_) ? std::max(kSetUpLimit, stepping) : stepping;
}

void StallWatch::check() const {
  const double waited = std::chrono::duration<double>(Clock::now() - wait_start_).count();
  const double limit = limit_s();
  if (waited <= limit) return;
  std::ostringstream m;
  m.precision(3);
  m << peer_ << " has sent nothing for " << waited << " s (limit " << limit << " s, "
    << (timeout_s_ > 0 ? "coupling.stall_timeout"
                       : "automatic: coupling.stall_timeout not set, docs/reliability.md")
    << ") while this program waits for "
    << (kind_ == Wait::packets ? "its packets" : "the agreement of both programs") << " at step "
    << step_
    << ": one of its ranks is stopped, hung or deadlocked; this program's last completed exchange: "
    << (last_completed_ >= 0 ? "step " + std::to_string(last_completed_) : std::string("none"))
    << "; last checkpoint: "
    << (remembered_checkpoint().empty() ? std::string("none")
                                        : remembered_checkpoint() + " (continue with --restart " +
                                              remembered_checkpoint() + " on both programs)");
  throw SideError(m.str());
}

std::string describe_stall_limit(const Scene& scene) {
  std::ostringstream m;
  m.precision(3);
  const double fixed = scene.coupling.stall_timeout;
  if (fixed > 0) {
    m << "stall limit: " << fixed << " s (coupling.stall_timeout): a side that waits longer for "
      << "the other's packets ends the job";
    return m.str();
  }
  m << "stall limit: automatic (coupling.stall_timeout not set): " << StallWatch::kSetUpLimit
    << " s for the first two exchanges (the other program's set-up and first step), then the "
    << "larger of " << StallWatch::kAutomaticFloor << " s and " << StallWatch::kAutomaticFactor
    << " x the slowest exchange so far, the agreements at stability steps included";
  if (scene.fluid && scene.coupling.checkpoint_interval > 0) {
    // One copy of the 19 populations per cell: what a fluid checkpoint holds.
    const auto& c = scene.fluid->cells;
    const double gib = double(c[0]) * c[1] * c[2] * 19 *
                       (scene.fluid->precision == Precision::float32 ? 4 : 8) /
                       (1024.0 * 1024.0 * 1024.0);
    m << "; a fluid checkpoint holds " << gib << " GiB: the waits around a checkpoint (or a field "
      << "output) allow at least " << StallWatch::kSetUpLimit << " s (at least "
      << gib / StallWatch::kSetUpLimit * 1024
      << " MiB/s to write it), else set coupling.stall_timeout";
  }
  return m.str();
}

}  // namespace lbdem
