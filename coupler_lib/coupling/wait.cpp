#include "coupler_lib/coupling/wait.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace lbdem {

namespace {

constexpr std::chrono::microseconds kFirstSleep{50};
constexpr std::chrono::microseconds kLongestSleep{2000};

// Test, sleep, test again with a growing sleep; stops early at `deadline`.
bool test_with_backoff(MPI_Request& request, std::chrono::steady_clock::time_point deadline,
                       const std::function<void()>& between_tests) {
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
