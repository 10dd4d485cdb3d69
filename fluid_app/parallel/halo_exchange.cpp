#include "fluid_app/parallel/halo_exchange.hpp"

#include "fluid_app/lattice/d3q19.hpp"

namespace lbdem {

namespace {

template <class T>
MPI_Datatype mpi_type() {
  return sizeof(T) == sizeof(double) ? MPI_DOUBLE : MPI_FLOAT;
}

// Range of one axis of the region beyond side e (e = 0: the interior span).
void region(int e, int n, int& lo, int& hi) {
  if (e == 0) {
    lo = 1;
    hi = n;
  } else {
    lo = hi = (e > 0 ? n + 1 : 0);
  }
}

}  // namespace

template <class T>
HaloExchange<T>::HaloExchange(const Decomposition& dec, CellIndex stride)
    : comm_(dec.comm()), rank_(dec.rank()) {
  using namespace d3q19;
  const LocalBox& b = dec.box();
  for (int ez = -1; ez <= 1; ++ez)
    for (int ey = -1; ey <= 1; ++ey)
      for (int ex = -1; ex <= 1; ++ex) {
        if (ex == 0 && ey == 0 && ez == 0) continue;
        Links& l = links_[direction(ex, ey, ez)];
        l.e = {ex, ey, ez};
        l.neighbour = dec.neighbour(ex, ey, ez);
        if (l.neighbour == MPI_PROC_NULL) continue;
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) region(l.e[a], b.n[a], lo[a], hi[a]);
        for (int j = 0; j < Q; ++j) {
          // Ghost g beyond side e whose source g - c_j is interior.
          for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
              for (int x = lo[0]; x <= hi[0]; ++x)
                if (b.interior(x - c[j][0], y - c[j][1], z - c[j][2]))
                  l.ghost.push_back(j * stride + b.index(x, y, z));
          // Interior y whose source y - c_j lies beyond side e.
          int ilo[3], ihi[3];
          for (int a = 0; a < 3; ++a) {
            ilo[a] = l.e[a] > 0 ? b.n[a] : 1;
            ihi[a] = l.e[a] < 0 ? 1 : b.n[a];
          }
          for (int z = ilo[2]; z <= ihi[2]; ++z)
            for (int y = ilo[1]; y <= ihi[1]; ++y)
              for (int x = ilo[0]; x <= ihi[0]; ++x) {
                const int s[3] = {x - c[j][0], y - c[j][1], z - c[j][2]};
                bool in = true;
                for (int a = 0; a < 3; ++a) in = in && s[a] >= lo[a] && s[a] <= hi[a];
                if (in) l.inner.push_back(j * stride + b.index(x, y, z));
              }
        }
        if (l.neighbour == rank_) continue;  // copied in place by finish(): no buffers
        l.send.resize(l.inner.size());
        l.recv.resize(l.ghost.size());
      }
}

template <class T>
void HaloExchange<T>::start(T* f, bool after_odd) {
  requests_.clear();
  ++traffic_.exchanges;
  for (int dir = 0; dir < 27; ++dir) {
    Links& l = links_[dir];
    if (l.neighbour == MPI_PROC_NULL || l.neighbour == rank_ || l.ghost.empty()) continue;
    // The message from the neighbour at e carries its tag for direction -e.
    const int back = direction(-l.e[0], -l.e[1], -l.e[2]);
    const std::vector<CellIndex>& from = after_odd ? l.ghost : l.inner;
    l.send.resize(from.size());
    l.recv.resize(after_odd ? l.inner.size() : l.ghost.size());
    requests_.emplace_back();
    MPI_Irecv(l.recv.data(), int(l.recv.size()), mpi_type<T>(), l.neighbour, back, comm_,
              &requests_.back());
    for (std::size_t k = 0; k < from.size(); ++k) l.send[k] = f[from[k]];
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
    if (l.neighbour != rank_ || l.ghost.empty()) continue;
    const Links& back = links_[direction(-l.e[0], -l.e[1], -l.e[2])];
    if (after_odd) {
      for (std::size_t k = 0; k < l.ghost.size(); ++k) f[back.inner[k]] = f[l.ghost[k]];
    } else {
      for (std::size_t k = 0; k < l.inner.size(); ++k) f[back.ghost[k]] = f[l.inner[k]];
    }
  }
  if (requests_.empty()) return;
  MPI_Waitall(int(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
  requests_.clear();
  for (int dir = 0; dir < 27; ++dir) {
    const Links& l = links_[dir];
    if (l.neighbour == MPI_PROC_NULL || l.neighbour == rank_ || l.ghost.empty()) continue;
    const std::vector<CellIndex>& to = after_odd ? l.inner : l.ghost;
    for (std::size_t k = 0; k < to.size(); ++k) f[to[k]] = l.recv[k];
  }
}

template class HaloExchange<double>;
template class HaloExchange<float>;

}  // namespace lbdem
