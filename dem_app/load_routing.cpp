#include "dem_app/load_routing.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace lbdem {

namespace {

// Sends out[r] to each rank r that has something to receive and returns what each rank sent
// here, by source rank: one MPI_Alltoall of the sizes, then point-to-point messages.
template <class T>
std::vector<std::vector<T>> sparse_exchange(const std::vector<std::vector<T>>& out, MPI_Comm comm,
                                            LoadTraffic& traffic) {
  static_assert(std::is_trivially_copyable_v<T>);
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const auto n = static_cast<std::size_t>(size);
  std::vector<int> send(n), recv(n);
  for (std::size_t r = 0; r < n; ++r) {
    if (out[r].size() * sizeof(T) > static_cast<std::size_t>(INT32_MAX))
      throw std::length_error("load exchange: a message of more than 2 GiB");
    send[r] = static_cast<int>(out[r].size() * sizeof(T));
  }
  MPI_Alltoall(send.data(), 1, MPI_INT, recv.data(), 1, MPI_INT, comm);
  std::vector<std::vector<T>> in(n);
  std::vector<MPI_Request> requests;
  for (std::size_t r = 0; r < n; ++r) {
    if (static_cast<int>(r) == rank || recv[r] == 0) continue;
    in[r].resize(static_cast<std::size_t>(recv[r]) / sizeof(T));
    requests.emplace_back();
    MPI_Irecv(in[r].data(), recv[r], MPI_BYTE, static_cast<int>(r), 0, comm, &requests.back());
    traffic.bytes += recv[r];
    ++traffic.messages;
  }
  for (std::size_t r = 0; r < n; ++r) {
    if (static_cast<int>(r) == rank || send[r] == 0) continue;
    requests.emplace_back();
    MPI_Isend(out[r].data(), send[r], MPI_BYTE, static_cast<int>(r), 0, comm, &requests.back());
  }
  in[static_cast<std::size_t>(rank)] = out[static_cast<std::size_t>(rank)];
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  traffic.bytes += static_cast<long long>((n - 1) * sizeof(int));
  return in;
}

}  // namespace

void deliver_loads(const std::vector<LoadUpdate>& pending, LoadTable& table, MPI_Comm comm,
                   LoadTraffic& traffic) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<std::vector<LoadUpdate>> out(static_cast<std::size_t>(size));
  for (const LoadUpdate& u : pending) {
    if (u.id < 0 || u.id >= table.bodies())
      throw std::out_of_range("load for unknown body " + std::to_string(u.id));
    out[static_cast<std::size_t>(table.home(u.id))].push_back(u);
  }
  for (const auto& from : sparse_exchange(out, comm, traffic))
    for (const LoadUpdate& u : from) table.update(u);
  ++traffic.exchanges;
}

std::vector<AppliedLoad> fetch_loads(const std::vector<std::int64_t>& bodies,
                                     const LoadTable& table, bool kick, MPI_Comm comm,
                                     LoadTraffic& traffic) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  const auto n = static_cast<std::size_t>(size);
  std::vector<std::vector<std::int64_t>> asked(n);
  for (std::int64_t id : bodies) asked[static_cast<std::size_t>(table.home(id))].push_back(id);
  const auto questions = sparse_exchange(asked, comm, traffic);
  std::vector<std::vector<AppliedLoad>> answers(n);
  for (std::size_t r = 0; r < n; ++r)
    for (std::int64_t id : questions[r]) answers[r].push_back(table.applied(id, kick));
  const auto replies = sparse_exchange(answers, comm, traffic);
  // Each home answered in the order asked; bodies are sorted, so walk them again.
  std::vector<AppliedLoad> out;
  out.reserve(bodies.size());
  std::vector<std::size_t> next(n, 0);
  for (std::int64_t id : bodies) {
    const auto h = static_cast<std::size_t>(table.home(id));
    out.push_back(replies[h].at(next[h]++));
  }
  return out;
}

}  // namespace lbdem
