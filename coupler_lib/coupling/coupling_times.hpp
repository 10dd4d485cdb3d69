#pragma once
// Where a program's coupling time goes, for the per-step breakdown of the benchmarks
// (fluid / DEM / exchange / idle), and what its coupler moved.
#include <chrono>
#include <cstdint>
#include <vector>

namespace lbdem {

struct CouplingTimes {
  std::int64_t calls = 0;  // coupler calls (receive_states, send_loads, ...)
  double total_s = 0;      // wall seconds inside those calls
  double idle_s = 0;       // of which: waiting for the other program
  // Packets this rank sent to and received from the other program: payload bytes and
  // non-empty buckets (one message each; the counts that precede them are not included).
  std::int64_t bytes = 0;
  std::int64_t messages = 0;

  double exchange_s() const { return total_s - idle_s; }  // routing, packing, transfer, checks
};

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
      : t_(t), start_(std::chrono::steady_clock::now()) {}
  ~ScopedCouplingTimer() {
    t_.calls += 1;
    t_.total_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  ScopedCouplingTimer(const ScopedCouplingTimer&) = delete;
  ScopedCouplingTimer& operator=(const ScopedCouplingTimer&) = delete;

 private:
  CouplingTimes& t_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace lbdem
