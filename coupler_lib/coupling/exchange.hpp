#pragma once
// One-way transfers of packets between the two groups of an intercommunicator: the fluid's
// loads to the DEM ranks, the DEM's states to the fluid ranks.
//
// Every rank of the sending group calls PacketSender::send with one bucket per rank of the
// other group (send[i] goes to remote rank i; empty buckets are fine) while every rank of the
// receiving group calls receive_packets for the same transfer. Each sender tells every remote
// rank its count, then sends its non-empty buckets, point to point, and returns at once: the
// sends complete in the background and are waited for at its next send. So a side never
// waits for the other to wake from its back-off sleep (wait.hpp) to hand over its packets, and
// a receiver waits only for packets that are not there yet. Packets between two ranks with one
// tag arrive in the order sent, so successive transfers cannot mix. The result holds, per
// remote rank in rank order, what it sent: the receive order never depends on message arrival.
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

// How a transfer waits: the wait mode, a check to run between tests (World::check_peer), and
// where to add the seconds spent waiting (for the other program's packets, or for the previous
// sends to complete).
struct ExchangeWait {
  ExchangeWait(WaitMode m = WaitMode::backoff) : mode(m) {}  // NOLINT: implicit on purpose
  ExchangeWait(WaitMode m, std::function<void()> check, double* waited)
      : mode(m), between_tests(std::move(check)), waited_s(waited) {}
  WaitMode mode;
  std::function<void()> between_tests;
  double* waited_s = nullptr;
};

int remote_size(MPI_Comm inter);

// The sending side of the transfers of one direction; it owns the buffers of the sends in
// flight.
class PacketSender {
 public:
  explicit PacketSender(MPI_Comm inter) : inter_(inter) {}
  PacketSender(const PacketSender&) = delete;
  PacketSender& operator=(const PacketSender&) = delete;
  // Completes the sends still in flight, except while an exception unwinds (the other program
  // may be gone): then they are released unfinished.
  ~PacketSender();

  template <class Packet>
  void send(const std::vector<std::vector<Packet>>& buckets, const ExchangeWait& wait) {
    static_assert(std::is_trivially_copyable_v<Packet>);
    std::vector<int> counts(buckets.size());
    size_t total = 0;
    for (size_t i = 0; i < buckets.size(); ++i) {
      const size_t n = buckets[i].size() * sizeof(Packet);
      if (n > static_cast<size_t>(INT32_MAX)) throw std::length_error("packet bucket over 2 GiB");
      counts[i] = static_cast<int>(n);
      total += n;
    }
    std::vector<std::byte> flat(total);
    size_t at = 0;
    for (const auto& b : buckets) {
      if (!b.empty()) std::memcpy(flat.data() + at, b.data(), b.size() * sizeof(Packet));
      at += b.size() * sizeof(Packet);
    }
    send_bytes(std::move(flat), std::move(counts), wait);
  }

  // Waits until the sends in flight have completed.
  void complete(const ExchangeWait& wait);

 private:
  void send_bytes(std::vector<std::byte> flat, std::vector<int> counts, const ExchangeWait& wait);

  MPI_Comm inter_;
  std::vector<int> counts_;        // what is in flight: the counts, one per remote rank,
  std::vector<std::byte> data_;    // the packets packed by rank,
  std::vector<MPI_Request> sent_;  // and their requests
};

// Receives one transfer: `counts[i]` bytes from remote rank i, packed by rank.
std::vector<std::byte> receive_bytes(MPI_Comm inter, std::vector<int>& counts,
                                     const ExchangeWait& wait);

template <class Packet>
std::vector<std::vector<Packet>> receive_packets(MPI_Comm inter, const ExchangeWait& wait) {
  static_assert(std::is_trivially_copyable_v<Packet>);
  std::vector<int> counts;
  const std::vector<std::byte> got = receive_bytes(inter, counts, wait);
  std::vector<std::vector<Packet>> out(counts.size());
  size_t at = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    const auto n = static_cast<size_t>(counts[i]);
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
