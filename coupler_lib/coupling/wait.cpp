#include "coupler_lib/coupling/wait.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace lbdem {

namespace {

constexpr std::chrono::microseconds kSpin{200};
constexpr std::chrono::microseconds kFirstSleep{50};
constexpr std::chrono::microseconds kLongestSleep{500};

// Test without sleeping for kSpin, then test, sleep, test again with a growing sleep; stops
// early at `deadline`. The spin serves the waits that end within microseconds (the rounds of a
// collective whose peers are already in it): sleeping there made every round cost a sleep on
// each side, about 1.5 ms per exchange.
bool test_with_backoff(MPI_Request& request, std::chrono::steady_clock::time_point deadline,
                       const std::function<void()>& between_tests) {
  const auto spin_end = std::chrono::steady_clock::now() + kSpin;
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return true;
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) return false;
    if (now >= spin_end) break;
  }
  auto sleep = kFirstSleep;
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    if (between_tests) between_tests();
    std::this_thread::sleep_for(sleep);
    sleep = std::min(sleep * 2, kLongestSleep);
  }
}

}  // namespace

void wait_request(MPI_Request& request, WaitMode mode, const std::function<void()>& between_tests) {
  if (mode == WaitMode::blocking) {
    if (!between_tests) {
      MPI_Wait(&request, MPI_STATUS_IGNORE);
      return;
    }
    for (int done = 0;;) {
      MPI_Test(&request, &done, MPI_STATUS_IGNORE);
      if (done) return;
      between_tests();
    }
  }
  test_with_backoff(request, std::chrono::steady_clock::time_point::max(), between_tests);
}

bool wait_request_until(MPI_Request& request, std::chrono::steady_clock::time_point deadline) {
  return test_with_backoff(request, deadline, {});
}

}  // namespace lbdem
