#pragma once
// Collectives within one program for lists of varying length (packets, body states): the
// one gather to rank 0 of the project, guarded against the int overflow of MPI counts.
#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace lbdem {

// Gathers every rank's `mine` on rank 0, by rank (empty result elsewhere).
template <class T>
std::vector<std::vector<T>> gather_by_rank(std::span<const T> mine, MPI_Comm comm) {
  static_assert(std::is_trivially_copyable_v<T>);
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int bytes = static_cast<int>(mine.size() * sizeof(T));
  std::vector<int> counts(rank == 0 ? static_cast<size_t>(size) : 0), displ(counts.size());
  MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  long long total = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    displ[i] = static_cast<int>(total);
    total += counts[i];
  }
  if (total > INT32_MAX) throw std::length_error("gather of more than 2 GiB of packets");
  std::vector<std::byte> all(static_cast<size_t>(total) + 1);
  MPI_Gatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, 0,
              comm);
  std::vector<std::vector<T>> out(counts.size());
  for (size_t i = 0; i < counts.size(); ++i) {
    out[i].resize(static_cast<size_t>(counts[i]) / sizeof(T));
    if (counts[i])
      std::memcpy(out[i].data(), all.data() + displ[i], static_cast<size_t>(counts[i]));
  }
  return out;
}

// Every rank's `mine` concatenated in rank order on rank 0 (empty elsewhere); the same
// overflow guard as gather_by_rank.
template <class T>
std::vector<T> gather_to_root(std::span<const T> mine, MPI_Comm comm) {
  std::vector<T> all;
  for (const auto& part : gather_by_rank(mine, comm))
    all.insert(all.end(), part.begin(), part.end());
  return all;
}

// Rank `root`'s `v` on every rank.
template <class T>
void broadcast(std::vector<T>& v, int root, MPI_Comm comm) {
  static_assert(std::is_trivially_copyable_v<T>);
  unsigned long long n = v.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, root, comm);
  v.resize(n);
  if (n) MPI_Bcast(v.data(), static_cast<int>(n * sizeof(T)), MPI_BYTE, root, comm);
}

}  // namespace lbdem
