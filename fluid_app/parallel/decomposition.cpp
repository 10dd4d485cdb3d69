#include "fluid_app/parallel/decomposition.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace lbdem {

Extent block_extent(int n, int p, int r) {
  const int base = n / p, extra = n % p;
  return {base + (r < extra ? 1 : 0), r * base + (r < extra ? r : extra)};
}

Extent weighted_extent(const std::vector<double>& w, int p, int r) {
  const int n = static_cast<int>(w.size());
  std::vector<double> cumulative(w.size() + 1, 0.0);
  for (int i = 0; i < n; ++i)
    cumulative[std::size_t(i) + 1] = cumulative[std::size_t(i)] + w[std::size_t(i)];
  // Cut k (1..p-1) at the first cell boundary where the cumulative weight reaches k/p of the
  // total, kept at least one cell from its neighbours so that no block is empty.
  auto cut = [&](int k) {
    if (k <= 0) return 0;
    if (k >= p) return n;
    const double target = cumulative.back() * double(k) / double(p);
    const int at =
        int(std::lower_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin());
    return std::clamp(at, k, n - (p - k));
  };
  // Cuts computed in order so that each is at least one past the previous one.
  int lo = 0;
  for (int k = 1; k <= r; ++k) lo = std::max(cut(k), lo + 1);
  int hi = r + 1 >= p ? n : std::max(cut(r + 1), lo + 1);
  return {hi - lo, lo};
}

Decomposition::Decomposition(MPI_Comm comm, std::array<int, 3> global, std::array<bool, 3> periodic,
                             std::array<int, 3> dims,
                             const std::array<std::vector<double>, 3>& weights)
    : periodic_(periodic) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  const bool automatic = dims[0] == 0 && dims[1] == 0 && dims[2] == 0;
  if (MPI_Dims_create(size, 3, dims.data()) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Dims_create failed for " + std::to_string(size) + " ranks");
  dims_ = dims;
  if (automatic) {
    // MPI_Dims_create gives balanced factors, largest first. Hand them to the axes from the
    // longest to the shortest, so cuts go across the long axes (small halos). x counts half
    // its length: cutting x makes short rows and strided halos, so it is cut last.
    std::array<int, 3> order = {2, 1, 0};
    const auto weight = [&](int a) { return a == 0 ? 0.5 * global[0] : double(global[a]); };
    std::stable_sort(order.begin(), order.end(),
                     [&](int l, int r) { return weight(l) > weight(r); });
    for (int k = 0; k < 3; ++k) dims_[order[k]] = dims[k];
  }
  for (int a = 0; a < 3; ++a)
    if (dims_[a] > global[a])
      throw std::runtime_error("cannot split " + std::to_string(global[a]) + " cells along axis " +
                               std::to_string(a) + " over " + std::to_string(dims_[a]) +
                               " ranks: use fewer ranks or a finer lattice");
  const int periods[3] = {periodic[0], periodic[1], periodic[2]};
  MPI_Cart_create(comm, 3, dims_.data(), periods, 0, &cart_);
  MPI_Comm_rank(cart_, &rank_);
  MPI_Comm_size(cart_, &size_);
  MPI_Cart_coords(cart_, rank_, 3, coords_.data());
  box_.global = global;
  for (int a = 0; a < 3; ++a) {
    const bool weighted = weights[a].size() == std::size_t(global[a]);
    const Extent e = weighted ? weighted_extent(weights[a], dims_[a], coords_[a])
                              : block_extent(global[a], dims_[a], coords_[a]);
    box_.n[a] = e.count;
    box_.offset[a] = e.offset;
  }
  for (int ez = -1; ez <= 1; ++ez)
    for (int ey = -1; ey <= 1; ++ey)
      for (int ex = -1; ex <= 1; ++ex) {
        const int e[3] = {ex, ey, ez};
        int c[3];
        bool exists = true;
        for (int a = 0; a < 3; ++a) {
          c[a] = coords_[a] + e[a];
          if (c[a] < 0 || c[a] >= dims_[a]) {
            if (!periodic_[a]) exists = false;
            c[a] = (c[a] + dims_[a]) % dims_[a];
          }
        }
        int r = MPI_PROC_NULL;
        if (exists) MPI_Cart_rank(cart_, c, &r);
        neighbour_[(ex + 1) + 3 * (ey + 1) + 9 * (ez + 1)] = r;
      }
}

Decomposition::~Decomposition() {
  int finalized = 0;
  MPI_Finalized(&finalized);  // a solver outliving MPI must not take the program down
  if (cart_ != MPI_COMM_NULL && !finalized) MPI_Comm_free(&cart_);
}

Decomposition::Decomposition(Decomposition&& o) noexcept
    : cart_(std::exchange(o.cart_, MPI_COMM_NULL)),
      rank_(o.rank_),
      size_(o.size_),
      dims_(o.dims_),
      coords_(o.coords_),
      periodic_(o.periodic_),
      box_(o.box_),
      neighbour_(o.neighbour_) {}

}  // namespace lbdem
