#include "fluid_app/parallel/halo_exchange.hpp"

#include <algorithm>

namespace lbdem {

namespace {

template <class T>
MPI_Datatype mpi_type() {
  return sizeof(T) == sizeof(double) ? MPI_DOUBLE : MPI_FLOAT;
}

// Range of one axis of the region beyond side e (e = 0: the interior span), inclusive.
void region(int e, int n, int& lo, int& hi) {
  if (e == 0) {
    lo = 1;
    hi = n;
  } else {
    lo = hi = (e > 0 ? n + 1 : 0);
  }
}

std::size_t volume(const CellRange& r) {
  if (r.empty()) return 0;
  return std::size_t(r.hi[0] - r.lo[0]) * std::size_t(r.hi[1] - r.lo[1]) *
         std::size_t(r.hi[2] - r.lo[2]);
}

// Calls f(j, k, offset) for every entry k of a list: population j, element offset
// j * stride + cell.
template <class F>
void for_each_link(const auto& list, const LocalBox& b, CellIndex stride, F&& f) {
  std::size_t k = 0;
  for (int j = 0; j < d3q19::Q; ++j) {
    const CellRange& r = list.cells[j];
    if (r.empty()) continue;
    for (int z = r.lo[2]; z < r.hi[2]; ++z)
      for (int y = r.lo[1]; y < r.hi[1]; ++y) {
        const CellIndex row = j * stride + b.index(0, y, z);
        for (int x = r.lo[0]; x < r.hi[0]; ++x) f(j, k++, row + x);
      }
  }
}

}  // namespace

template <class T>
HaloExchange<T>::HaloExchange(const Decomposition& dec, CellIndex stride)
    : comm_(dec.comm()), rank_(dec.rank()), box_(dec.box()), stride_(stride) {
  using namespace d3q19;
  const LocalBox& b = box_;
  for (int ez = -1; ez <= 1; ++ez)
    for (int ey = -1; ey <= 1; ++ey)
      for (int ex = -1; ex <= 1; ++ex) {
        if (ex == 0 && ey == 0 && ez == 0) continue;
        Links& l = links_[direction(ex, ey, ez)];
        l.e = {ex, ey, ez};
        l.neighbour = dec.neighbour(ex, ey, ez);
        if (l.neighbour == MPI_PROC_NULL) continue;
        for (int j = 0; j < Q; ++j) {
          CellRange& g = l.ghost.cells[j];
          CellRange& in = l.inner.cells[j];
          for (int a = 0; a < 3; ++a) {
            int lo = 0, hi = 0;
            region(l.e[a], b.n[a], lo, hi);
            // Ghost g beyond side e whose source g - c_j is interior (1 <= g - c_j <= n).
            g.lo[a] = std::max(lo, 1 + c[j][a]);
            g.hi[a] = std::min(hi, b.n[a] + c[j][a]) + 1;
            // Interior y at side e (the layer 1 or n, or the whole span) whose source y - c_j
            // lies beyond side e.
            const int ilo = l.e[a] > 0 ? b.n[a] : 1, ihi = l.e[a] < 0 ? 1 : b.n[a];
            in.lo[a] = std::max(ilo, lo + c[j][a]);
            in.hi[a] = std::min(ihi, hi + c[j][a]) + 1;
          }
          l.ghost.size += volume(g);
          l.inner.size += volume(in);
        }
        if (l.neighbour == rank_) continue;  // copied in place by finish(): no buffers
        l.send.resize(l.inner.size);
        l.recv.resize(l.ghost.size);
      }
}

template <class T>
void HaloExchange<T>::start(T* f, bool after_odd) {
  requests_.clear();
  ++traffic_.exchanges;
  for (int dir = 0; dir < 27; ++dir) {
    Links& l = links_[dir];
    if (l.neighbour == MPI_PROC_NULL || l.neighbour == rank_ || l.ghost.size == 0) continue;
    // The message from the neighbour at e carries its tag for direction -e.
    const int back = direction(-l.e[0], -l.e[1], -l.e[2]);
    const LinkBoxes& from = after_odd ? l.ghost : l.inner;
    l.send.resize(from.size);
    l.recv.resize(after_odd ? l.inner.size : l.ghost.size);
    requests_.emplace_back();
    MPI_Irecv(l.recv.data(), int(l.recv.size()), mpi_type<T>(), l.neighbour, back, comm_,
              &requests_.back());
    for_each_link(from, box_, stride_,
                  [&](int, std::size_t k, CellIndex at) { l.send[k] = f[at]; });
    requests_.emplace_back();
    MPI_Isend(l.send.data(), int(l.send.size()), mpi_type<T>(), l.neighbour, dir, comm_,
              &requests_.back());
    traffic_.bytes += static_cast<long long>(l.send.size() * sizeof(T));
    ++traffic_.messages;
  }
}

template <class T>
void HaloExchange<T>::finish(T* f, bool after_odd) {
  // Links to ourselves: what we send towards e arrives from -e.
  for (int dir = 0; dir < 27; ++dir) {
    const Links& l = links_[dir];
    if (l.neighbour != rank_ || l.ghost.size == 0) continue;
    // Population j's box of our list and of the back list are the same links, the one box
    // shifted by the period: the same cells in the same order, a fixed offset apart.
    const Links& back = links_[direction(-l.e[0], -l.e[1], -l.e[2])];
    const LinkBoxes& from = after_odd ? l.ghost : l.inner;
    const LinkBoxes& to = after_odd ? back.inner : back.ghost;
    std::array<CellIndex, d3q19::Q> shift{};
    for (int j = 0; j < d3q19::Q; ++j) {
      const CellRange &s = from.cells[j], &t = to.cells[j];
      shift[j] = box_.index(t.lo[0], t.lo[1], t.lo[2]) - box_.index(s.lo[0], s.lo[1], s.lo[2]);
    }
    for_each_link(from, box_, stride_,
                  [&](int j, std::size_t, CellIndex at) { f[at + shift[j]] = f[at]; });
  }
  if (requests_.empty()) return;
  MPI_Waitall(int(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
  requests_.clear();
  for (int dir = 0; dir < 27; ++dir) {
    const Links& l = links_[dir];
    if (l.neighbour == MPI_PROC_NULL || l.neighbour == rank_ || l.ghost.size == 0) continue;
    for_each_link(after_odd ? l.inner : l.ghost, box_, stride_,
                  [&](int, std::size_t k, CellIndex at) { f[at] = l.recv[k]; });
  }
}

template class HaloExchange<double>;
template class HaloExchange<float>;

}  // namespace lbdem
