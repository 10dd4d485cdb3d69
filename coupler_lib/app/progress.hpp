#pragma once
// A progress line at a fixed wall-time interval: step, simulated time, percent, ETA and
// throughput (steps per second and, if given, million lattice updates per second).
#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdint>
#include <memory>

namespace lbdem {

class Progress {
 public:
  Progress(std::shared_ptr<spdlog::logger> log, double interval_s, double end_time,
           double cells_per_step = 0);
  // Cheap to call every step: looks at the clock only every few calls.
  void update(std::int64_t step, double time);
  // Steps per second from the first progress line to the last (the first interval is the
  // warm-up: caches, first embedding, set-up runs); 0 with fewer than two lines.
  double steps_per_s_after_first_line() const;

 private:
  using Clock = std::chrono::steady_clock;
  std::shared_ptr<spdlog::logger> log_;
  double interval_;
  double end_;
  double cells_;
  Clock::time_point start_, last_, first_line_;
  std::int64_t last_step_ = 0, first_line_step_ = 0;
  int lines_ = 0;
};

}  // namespace lbdem
