#include "coupler_lib/app/progress.hpp"

namespace lbdem {

Progress::Progress(std::shared_ptr<spdlog::logger> log, double interval_s, double end_time,
                   double cells_per_step)
    : log_(std::move(log)),
      interval_(interval_s),
      end_(end_time),
      cells_(cells_per_step),
      start_(Clock::now()),
      last_(start_) {}

void Progress::update(std::int64_t step, double time) {
  const auto now = Clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (since < interval_) return;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double frac = end_ > 0 ? time / end_ : 0.0;
  const double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0.0;
  const double sps = (step - last_step_) / since;
  if (cells_ > 0) {
    log_->info("step {} t={:.4e} s {:.1f}% ETA {:.0f} s, {:.1f} steps/s, {:.1f} MLUPS", step, time,
               100 * frac, eta, sps, sps * cells_ * 1e-6);
  } else {
    log_->info("step {} t={:.4e} s {:.1f}% ETA {:.0f} s, {:.1f} steps/s", step, time, 100 * frac,
               eta, sps);
  }
  last_ = now;
  last_step_ = step;
  if (lines_++ == 0) {
    first_line_ = now;
    first_line_step_ = step;
  }
}

double Progress::steps_per_s_after_first_line() const {
  const double s = std::chrono::duration<double>(last_ - first_line_).count();
  return lines_ >= 2 && s > 0 ? double(last_step_ - first_line_step_) / s : 0.0;
}

}  // namespace lbdem
