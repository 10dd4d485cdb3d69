#include "coupler_lib/coupling/exchange.hpp"

#include <chrono>
#include <exception>

namespace lbdem {

namespace {

// Tags on the intercommunicator (the hello of world.cpp uses another one).
constexpr int kCountTag = 4720;
constexpr int kPacketTag = 4721;

// Completes every request, adding the seconds to `wait.waited_s`.
void wait_all(std::vector<MPI_Request>& requests, const ExchangeWait& wait) {
  const auto t0 = std::chrono::steady_clock::now();
  for (MPI_Request& r : requests) wait_request(r, wait.mode, wait.between_tests);
  requests.clear();
  if (wait.waited_s)
    *wait.waited_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int remote_size(MPI_Comm inter) {
  int n = 0;
  MPI_Comm_remote_size(inter, &n);
  return n;
}

PacketSender::~PacketSender() {
  if (std::uncaught_exceptions() > 0) {
    // The run is failing and both programs are stopping: what a receiver would still read
    // no longer matters, and waiting could hang on a program that is gone.
    for (MPI_Request& r : sent_) MPI_Request_free(&r);
    return;
  }
  // Every packet of a run that ends normally has been received by then (each side's last
  // receive follows the other's last send); the deadline only keeps a vanished peer from
  // holding this process forever.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  for (MPI_Request& r : sent_)
    if (!wait_request_until(r, deadline)) MPI_Request_free(&r);
}

void PacketSender::complete(const ExchangeWait& wait) {
  wait_all(sent_, wait);
}

void PacketSender::send_bytes(std::vector<std::byte> flat, std::vector<int> counts,
                              const ExchangeWait& wait) {
  const int n = remote_size(inter_);
  if (static_cast<int>(counts.size()) != n)
    throw std::invalid_argument("transfer: " + std::to_string(counts.size()) +
                                " send buckets for " + std::to_string(n) + " remote ranks");
  complete(wait);
  counts_ = std::move(counts);
  data_ = std::move(flat);
  size_t at = 0;
  for (int i = 0; i < n; ++i) {
    const int count = counts_[static_cast<size_t>(i)];
    sent_.emplace_back();
    MPI_Isend(&counts_[static_cast<size_t>(i)], 1, MPI_INT, i, kCountTag, inter_, &sent_.back());
    if (count > 0) {
      sent_.emplace_back();
      MPI_Isend(data_.data() + at, count, MPI_BYTE, i, kPacketTag, inter_, &sent_.back());
    }
    at += static_cast<size_t>(count);
  }
}

std::vector<std::byte> receive_bytes(MPI_Comm inter, std::vector<int>& counts,
                                     const ExchangeWait& wait) {
  const int n = remote_size(inter);
  counts.assign(static_cast<size_t>(n), 0);
  std::vector<MPI_Request> requests(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i)
    MPI_Irecv(&counts[static_cast<size_t>(i)], 1, MPI_INT, i, kCountTag, inter,
              &requests[static_cast<size_t>(i)]);
  wait_all(requests, wait);
  long long total = 0;
  for (int c : counts) total += c;
  if (total > INT32_MAX)
    throw std::length_error("transfer: more than 2 GiB of packets in one step");
  std::vector<std::byte> recv(static_cast<size_t>(total));
  size_t at = 0;
  for (int i = 0; i < n; ++i) {
    const int count = counts[static_cast<size_t>(i)];
    if (count > 0) {
      requests.emplace_back();
      MPI_Irecv(recv.data() + at, count, MPI_BYTE, i, kPacketTag, inter, &requests.back());
    }
    at += static_cast<size_t>(count);
  }
  wait_all(requests, wait);
  return recv;
}

}  // namespace lbdem
