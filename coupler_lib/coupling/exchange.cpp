#include "coupler_lib/coupling/exchange.hpp"

#include <chrono>

namespace lbdem {

int remote_size(MPI_Comm inter) {
  int n = 0;
  MPI_Comm_remote_size(inter, &n);
  return n;
}

std::vector<std::byte> exchange_bytes(MPI_Comm inter, const std::vector<std::byte>& send,
                                      const std::vector<int>& send_counts,
                                      std::vector<int>& recv_counts, const ExchangeWait& wait) {
  const int n = remote_size(inter);
  if (static_cast<int>(send_counts.size()) != n)
    throw std::invalid_argument("exchange: " + std::to_string(send_counts.size()) +
                                " send buckets for " + std::to_string(n) + " remote ranks");
  recv_counts.assign(static_cast<size_t>(n), 0);
  MPI_Request req;
  const auto t0 = std::chrono::steady_clock::now();
  MPI_Ialltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, inter, &req);
  wait_request(req, wait.mode, wait.between_tests);
  if (wait.waited_s)
    *wait.waited_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::vector<int> sdispl(static_cast<size_t>(n)), rdispl(static_cast<size_t>(n));
  long long s = 0, r = 0;
  for (size_t i = 0; i < static_cast<size_t>(n); ++i) {
    sdispl[i] = static_cast<int>(s);
    rdispl[i] = static_cast<int>(r);
    s += send_counts[i];
    r += recv_counts[i];
  }
  if (s > INT32_MAX || r > INT32_MAX)
    throw std::length_error("exchange: more than 2 GiB of packets in one step");
  std::vector<std::byte> recv(static_cast<size_t>(r));
  // Never hand MPI a null buffer pointer, even for zero counts.
  std::byte dummy{};
  const void* sbuf = send.empty() ? static_cast<const void*>(&dummy) : send.data();
  void* rbuf = recv.empty() ? static_cast<void*>(&dummy) : recv.data();
  MPI_Ialltoallv(sbuf, send_counts.data(), sdispl.data(), MPI_BYTE, rbuf, recv_counts.data(),
                 rdispl.data(), MPI_BYTE, inter, &req);
  wait_request(req, wait.mode, wait.between_tests);
  return recv;
}

}  // namespace lbdem
