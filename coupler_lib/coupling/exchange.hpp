#pragma once
// One all-to-all exchange of packets between the two groups of an intercommunicator.
//
// Every rank of both binaries calls it together; send[i] goes to rank i of the other group
// (send.size() == remote size; empty buckets are fine, so a one-way transfer is the same
// call with nothing to send on one side). Counts are exchanged first, then the packets, both
// as nonblocking collectives completed with the caller's wait mode, so a side that arrives
// early sleeps instead of spinning. The result holds, per remote rank in rank order, what
// it sent: the receive order never depends on message arrival.
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "coupler_lib/coupling/wait.hpp"

namespace lbdem {

// How an exchange waits: the wait mode, a check to run between tests (World::check_peer), and
// where to add the seconds spent waiting for the other program (the counts phase, which
// completes only once the other program has called the exchange too).
struct ExchangeWait {
  ExchangeWait(WaitMode m = WaitMode::backoff) : mode(m) {}  // NOLINT: implicit on purpose
  ExchangeWait(WaitMode m, std::function<void()> check, double* waited)
      : mode(m), between_tests(std::move(check)), waited_s(waited) {}
  WaitMode mode;
  std::function<void()> between_tests;
  double* waited_s = nullptr;
};

// Bytes version: `send_counts[i]` bytes of `send` (packed by rank) go to remote rank i.
// Returns the received bytes packed by rank and fills `recv_counts`.
std::vector<std::byte> exchange_bytes(MPI_Comm inter, const std::vector<std::byte>& send,
                                      const std::vector<int>& send_counts,
                                      std::vector<int>& recv_counts, const ExchangeWait& wait);

int remote_size(MPI_Comm inter);

template <class Packet>
std::vector<std::vector<Packet>> exchange(MPI_Comm inter,
                                          const std::vector<std::vector<Packet>>& send,
                                          const ExchangeWait& wait) {
  static_assert(std::is_trivially_copyable_v<Packet>);
  std::vector<int> send_counts(send.size());
  size_t total = 0;
  for (const auto& b : send) total += b.size() * sizeof(Packet);
  std::vector<std::byte> flat(total);
  size_t at = 0;
  for (size_t i = 0; i < send.size(); ++i) {
    const size_t n = send[i].size() * sizeof(Packet);
    if (n > static_cast<size_t>(INT32_MAX)) throw std::length_error("packet bucket over 2 GiB");
    if (n) std::memcpy(flat.data() + at, send[i].data(), n);
    send_counts[i] = static_cast<int>(n);
    at += n;
  }
  std::vector<int> recv_counts;
  const std::vector<std::byte> got = exchange_bytes(inter, flat, send_counts, recv_counts, wait);
  std::vector<std::vector<Packet>> out(recv_counts.size());
  at = 0;
  for (size_t i = 0; i < recv_counts.size(); ++i) {
    const auto n = static_cast<size_t>(recv_counts[i]);
    if (n % sizeof(Packet) != 0)
      throw std::runtime_error("received " + std::to_string(n) + " bytes from remote rank " +
                               std::to_string(i) + ", not a whole number of " +
                               std::to_string(sizeof(Packet)) + "-byte packets");
    out[i].resize(n / sizeof(Packet));
    if (n) std::memcpy(out[i].data(), got.data() + at, n);
    at += n;
  }
  return out;
}

}  // namespace lbdem
