#include "fluid_app/parallel/move_blocks.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <type_traits>

namespace lbdem {

namespace {

// Global cells [lo, hi) per axis.
struct Region {
  std::array<int, 3> lo{}, hi{};
  std::int64_t cells() const {
    std::int64_t c = 1;
    for (int a = 0; a < 3; ++a) c *= std::max(0, hi[a] - lo[a]);
    return c;
  }
};

Region overlap(const int* a, const int* b) {  // each: offset[3], n[3]
  Region r;
  for (int k = 0; k < 3; ++k) {
    r.lo[k] = std::max(a[k], b[k]);
    r.hi[k] = std::min(a[k] + a[3 + k], b[k] + b[3 + k]);
  }
  return r;
}

// Calls f(position in a block's component-major array) for every cell of `r`, component by
// component, z slowest, x fastest: the order both ends of a transfer agree on.
template <class F>
void visit(const Region& r, int components, const LocalBox& box, F&& f) {
  const std::int64_t cells = box.interior_cells();
  for (int c = 0; c < components; ++c)
    for (int z = r.lo[2]; z < r.hi[2]; ++z)
      for (int y = r.lo[1]; y < r.hi[1]; ++y) {
        const std::int64_t row =
            c * cells + (std::int64_t(z - box.offset[2]) * box.n[1] + (y - box.offset[1])) *
                            std::int64_t(box.n[0]);
        for (int x = r.lo[0]; x < r.hi[0]; ++x) f(row + (x - box.offset[0]));
      }
}

}  // namespace

template <class T>
std::vector<T> move_blocks(const std::vector<T>& values, int components, const LocalBox& from,
                           const LocalBox& to, MPI_Comm comm) {
  static_assert(std::is_same_v<T, double> || std::is_same_v<T, float>);
  const MPI_Datatype type = std::is_same_v<T, double> ? MPI_DOUBLE : MPI_FLOAT;
  int size = 1;
  MPI_Comm_size(comm, &size);
  // Every rank's old and new block: offset and size of each, 12 integers per rank.
  const int mine[12] = {from.offset[0], from.offset[1], from.offset[2], from.n[0],
                        from.n[1],      from.n[2],      to.offset[0],   to.offset[1],
                        to.offset[2],   to.n[0],        to.n[1],        to.n[2]};
  std::vector<int> all(12 * static_cast<std::size_t>(size));
  MPI_Allgather(mine, 12, MPI_INT, all.data(), 12, MPI_INT, comm);
  const auto ranks = static_cast<std::size_t>(size);
  std::vector<int> send_count(ranks), send_at(ranks), recv_count(ranks), recv_at(ranks);
  std::int64_t sent = 0, received = 0;
  for (int r = 0; r < size; ++r) {
    const std::int64_t out = overlap(mine, &all[std::size_t(12 * r + 6)]).cells() * components;
    const std::int64_t in = overlap(&all[std::size_t(12 * r)], mine + 6).cells() * components;
    send_at[std::size_t(r)] = int(sent);
    recv_at[std::size_t(r)] = int(received);
    send_count[std::size_t(r)] = int(out);
    recv_count[std::size_t(r)] = int(in);
    sent += out;
    received += in;
  }
  if (sent > INT32_MAX || received > INT32_MAX)
    throw std::length_error("move_blocks: a block of more than 2^31 values");
  std::vector<T> send(std::size_t(sent) + 1), recv(std::size_t(received) + 1);
  for (int r = 0; r < size; ++r) {
    std::size_t k = std::size_t(send_at[std::size_t(r)]);
    visit(overlap(mine, &all[std::size_t(12 * r + 6)]), components, from,
          [&](std::int64_t at) { send[k++] = values[std::size_t(at)]; });
  }
  MPI_Alltoallv(send.data(), send_count.data(), send_at.data(), type, recv.data(),
                recv_count.data(), recv_at.data(), type, comm);
  std::vector<T> out(std::size_t(components) * std::size_t(to.interior_cells()));
  for (int r = 0; r < size; ++r) {
    std::size_t k = std::size_t(recv_at[std::size_t(r)]);
    visit(overlap(&all[std::size_t(12 * r)], mine + 6), components, to,
          [&](std::int64_t at) { out[std::size_t(at)] = recv[k++]; });
  }
  return out;
}

template std::vector<double> move_blocks(const std::vector<double>&, int, const LocalBox&,
                                         const LocalBox&, MPI_Comm);
template std::vector<float> move_blocks(const std::vector<float>&, int, const LocalBox&,
                                        const LocalBox&, MPI_Comm);

}  // namespace lbdem
