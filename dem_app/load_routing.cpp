#include "dem_app/load_routing.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace lbdem {

namespace {

// The message to one home: the number of updates, the updates, then the ids asked for.
struct Message {
  std::vector<LoadUpdate> updates;
  std::vector<std::int64_t> asked;
};

std::vector<char> pack(const Message& m) {
  if (m.updates.empty() && m.asked.empty()) return {};
  const auto n = static_cast<std::int64_t>(m.updates.size());
  std::vector<char> b(sizeof n + m.updates.size() * sizeof(LoadUpdate) +
                      m.asked.size() * sizeof(std::int64_t));
  char* p = b.data();
  std::memcpy(p, &n, sizeof n);
  p += sizeof n;
  if (!m.updates.empty()) std::memcpy(p, m.updates.data(), m.updates.size() * sizeof(LoadUpdate));
  p += m.updates.size() * sizeof(LoadUpdate);
  if (!m.asked.empty()) std::memcpy(p, m.asked.data(), m.asked.size() * sizeof(std::int64_t));
  return b;
}

Message unpack(const std::vector<char>& b) {
  Message m;
  if (b.empty()) return m;
  std::int64_t n = 0;
  std::memcpy(&n, b.data(), sizeof n);
  const std::size_t rest = b.size() - sizeof n - static_cast<std::size_t>(n) * sizeof(LoadUpdate);
  m.updates.resize(static_cast<std::size_t>(n));
  m.asked.resize(rest / sizeof(std::int64_t));
  const char* p = b.data() + sizeof n;
  if (n > 0) std::memcpy(m.updates.data(), p, m.updates.size() * sizeof(LoadUpdate));
  p += m.updates.size() * sizeof(LoadUpdate);
  if (!m.asked.empty()) std::memcpy(m.asked.data(), p, m.asked.size() * sizeof(std::int64_t));
  return m;
}

int byte_count(std::size_t bytes) {
  if (bytes > static_cast<std::size_t>(INT32_MAX))
    throw std::length_error("load exchange: a message of more than 2 GiB");
  return static_cast<int>(bytes);
}

}  // namespace

std::vector<AppliedLoad> exchange_loads(const std::vector<LoadUpdate>& pending,
                                        const std::vector<std::int64_t>& bodies, LoadTable& table,
                                        LoadRun run, MPI_Comm comm, LoadTraffic& traffic) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const auto n = static_cast<std::size_t>(size);
  const auto self = static_cast<std::size_t>(rank);
  std::vector<Message> out(n);
  for (const LoadUpdate& u : pending) {
    if (u.id < 0 || u.id >= table.bodies())
      throw std::out_of_range("load for unknown body " + std::to_string(u.id));
    out[static_cast<std::size_t>(table.home(u.id))].updates.push_back(u);
  }
  for (std::int64_t id : bodies) out[static_cast<std::size_t>(table.home(id))].asked.push_back(id);

  // Updates and questions: sizes by MPI_Alltoall, then point-to-point.
  std::vector<std::vector<char>> send(n), recv(n);
  std::vector<int> send_bytes(n), recv_bytes(n);
  for (std::size_t r = 0; r < n; ++r) {
    send[r] = pack(out[r]);
    send_bytes[r] = byte_count(send[r].size());
  }
  MPI_Alltoall(send_bytes.data(), 1, MPI_INT, recv_bytes.data(), 1, MPI_INT, comm);
  traffic.bytes += static_cast<long long>((n - 1) * sizeof(int));
  std::vector<MPI_Request> requests;
  auto post = [&](bool receive, std::size_t r, void* data, int bytes, int tag) {
    if (r == self || bytes == 0) return;
    requests.emplace_back();
    if (receive) {
      MPI_Irecv(data, bytes, MPI_BYTE, static_cast<int>(r), tag, comm, &requests.back());
      traffic.bytes += bytes;
      ++traffic.messages;
    } else {
      MPI_Isend(data, bytes, MPI_BYTE, static_cast<int>(r), tag, comm, &requests.back());
    }
  };
  for (std::size_t r = 0; r < n; ++r) {
    recv[r].resize(static_cast<std::size_t>(recv_bytes[r]));
    post(true, r, recv[r].data(), recv_bytes[r], 0);
  }
  for (std::size_t r = 0; r < n; ++r) post(false, r, send[r].data(), send_bytes[r], 0);
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  requests.clear();
  recv[self] = send[self];

  // At the homes: all updates in rank order, then the answers.
  std::vector<Message> in(n);
  for (std::size_t r = 0; r < n; ++r) in[r] = unpack(recv[r]);
  for (const Message& m : in)
    for (const LoadUpdate& u : m.updates) table.update(u);
  if (run.begin) table.begin_run();
  std::vector<std::vector<AppliedLoad>> answers(n), replies(n);
  for (std::size_t r = 0; r < n; ++r)
    for (std::int64_t id : in[r].asked) answers[r].push_back(table.applied(id, run.kick));

  // Answers back, point-to-point: both sides know their sizes.
  for (std::size_t r = 0; r < n; ++r) {
    replies[r].resize(out[r].asked.size());
    post(true, r, replies[r].data(), byte_count(replies[r].size() * sizeof(AppliedLoad)), 1);
  }
  for (std::size_t r = 0; r < n; ++r)
    post(false, r, answers[r].data(), byte_count(answers[r].size() * sizeof(AppliedLoad)), 1);
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  replies[self] = answers[self];
  ++traffic.exchanges;

  // Each home answered in the order asked; bodies are sorted, so walk them again.
  std::vector<AppliedLoad> loads;
  loads.reserve(bodies.size());
  std::vector<std::size_t> next(n, 0);
  for (std::int64_t id : bodies) {
    const auto h = static_cast<std::size_t>(table.home(id));
    loads.push_back(replies[h][next[h]++]);
  }
  return loads;
}

}  // namespace lbdem
