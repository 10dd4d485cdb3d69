#pragma once
// Body output gathered on rank 0 in bounded pieces: consecutive ranges of kOutputChunk body
// ids, each gathered, sorted by id and written before the next is gathered, so rank 0 holds
// one piece (kOutputChunk x 128 bytes of states), never all the bodies at once.
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "coupler_lib/output/gather.hpp"

namespace lbdem {

inline constexpr std::int64_t kOutputChunk = 65536;

// A copy of `items` ordered by id, equal ids in their given order.
template <class T>
std::vector<T> sorted_by_id(std::span<const T> items) {
  std::vector<T> out(items.begin(), items.end());
  std::stable_sort(out.begin(), out.end(), [](const T& a, const T& b) { return a.id < b.id; });
  return out;
}

// One past the largest id on any rank, 0 when there is none (collective).
template <class T>
std::int64_t id_end(const std::vector<T>& sorted, MPI_Comm comm) {
  std::int64_t end = sorted.empty() ? 0 : sorted.back().id + 1;
  MPI_Allreduce(MPI_IN_PLACE, &end, 1, MPI_INT64_T, MPI_MAX, comm);
  return end;
}

// Every rank's items with ids in [lo, hi) on rank 0, ordered by id, equal ids in rank order
// (empty elsewhere). `sorted`: this rank's items ordered by id (collective).
template <class T>
std::vector<T> gather_id_range(const std::vector<T>& sorted, std::int64_t lo, std::int64_t hi,
                               MPI_Comm comm) {
  auto below = [](const T& a, std::int64_t id) { return a.id < id; };
  const auto first = std::lower_bound(sorted.begin(), sorted.end(), lo, below);
  const auto last = std::lower_bound(first, sorted.end(), hi, below);
  const std::span<const T> part(sorted.data() + (first - sorted.begin()),
                                static_cast<std::size_t>(last - first));
  std::vector<T> all = gather_to_root(part, comm);
  std::stable_sort(all.begin(), all.end(), [](const T& a, const T& b) { return a.id < b.id; });
  return all;
}

}  // namespace lbdem
