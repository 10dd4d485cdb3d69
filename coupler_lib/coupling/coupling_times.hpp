#pragma once
// Where a program's coupling time goes, for the per-step breakdown of the benchmarks
// (fluid / DEM / exchange / idle), and what its coupler moved.
#include <time.h>

#include <chrono>
#include <cstdint>
#include <vector>

namespace lbdem {

// CPU seconds this thread has used (CLOCK_THREAD_CPUTIME_ID): what a part costs on a core of
// its own, where the wall time on shared cores also holds the time other processes ran.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct CouplingTimes {
  std::int64_t calls = 0;  // coupler calls (receive_states, send_loads, ...)
  double total_s = 0;      // wall seconds inside those calls
  double idle_s = 0;       // of which: waiting for the other program
  double cpu_s = 0;        // CPU seconds of this thread in those calls (waits sleep: little)
  // Packets this rank sent to and received from the other program: payload bytes and
  // non-empty buckets (one message each; the counts that precede them are not included).
  std::int64_t bytes = 0;
  std::int64_t messages = 0;

  double exchange_s() const { return total_s - idle_s; }  // routing, packing, transfer, checks
};

// What happened between two readings of the same coupler's times (`later` minus `earlier`).
inline CouplingTimes since(const CouplingTimes& later, const CouplingTimes& earlier) {
  CouplingTimes d;
  d.calls = later.calls - earlier.calls;
  d.total_s = later.total_s - earlier.total_s;
  d.idle_s = later.idle_s - earlier.idle_s;
  d.cpu_s = later.cpu_s - earlier.cpu_s;
  d.bytes = later.bytes - earlier.bytes;
  d.messages = later.messages - earlier.messages;
  return d;
}

// Adds one exchange's buckets (one per rank of the other program) to the traffic.
template <class Packet>
void count_traffic(CouplingTimes& t, const std::vector<std::vector<Packet>>& buckets) {
  for (const auto& b : buckets)
    if (!b.empty()) {
      t.bytes += static_cast<std::int64_t>(b.size() * sizeof(Packet));
      ++t.messages;
    }
}

// Adds the wall time of its scope to a CouplingTimes.
class ScopedCouplingTimer {
 public:
  explicit ScopedCouplingTimer(CouplingTimes& t)
      : t_(t), start_(std::chrono::steady_clock::now()), cpu_start_(thread_cpu_seconds()) {}
  ~ScopedCouplingTimer() {
    t_.calls += 1;
    t_.total_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    t_.cpu_s += thread_cpu_seconds() - cpu_start_;
  }
  ScopedCouplingTimer(const ScopedCouplingTimer&) = delete;
  ScopedCouplingTimer& operator=(const ScopedCouplingTimer&) = delete;

 private:
  CouplingTimes& t_;
  std::chrono::steady_clock::time_point start_;
  double cpu_start_;
};

}  // namespace lbdem
