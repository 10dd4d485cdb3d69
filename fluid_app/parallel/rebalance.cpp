#include "fluid_app/parallel/rebalance.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>

#include "fluid_app/parallel/balance.hpp"
#include "fluid_app/parallel/decomposition.hpp"

namespace lbdem {

CheckpointWork measure_work(const LocalBox& box, std::span<const float> d,
                            double covered_cell_weight, MPI_Comm comm) {
  CheckpointWork w;
  for (int a = 0; a < 3; ++a) w.measured[a].assign(std::size_t(box.global[a]), 0.0);
  double covered = 0;
  for (int z = 1; z <= box.n[2]; ++z)
    for (int y = 1; y <= box.n[1]; ++y)
      for (int x = 1; x <= box.n[0]; ++x) {
        const bool c = !d.empty() && d[std::size_t(box.index(x, y, z))] < 1.0f;
        const double work = weighted_work(1, c ? 1 : 0, covered_cell_weight);
        covered += c;
        const int g[3] = {box.offset[0] + x - 1, box.offset[1] + y - 1, box.offset[2] + z - 1};
        for (int a = 0; a < 3; ++a) w.measured[a][std::size_t(g[a])] += work;
      }
  for (auto& m : w.measured)
    MPI_Allreduce(MPI_IN_PLACE, m.data(), int(m.size()), MPI_DOUBLE, MPI_SUM, comm);
  const double mine = weighted_work(double(box.interior_cells()), covered, covered_cell_weight);
  double most = mine, total = mine;
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_DOUBLE, MPI_SUM, comm);
  w.imbalance = most / (total / ranks);
  w.fluid_ranks = ranks;
  return w;
}

double imbalance_of_cuts(const LocalBox& box, std::span<const float> d, double covered_cell_weight,
                         const SliceWeights& weights, const std::array<int, 3>& dims,
                         MPI_Comm comm) {
  // The block index along each axis of every global slice.
  std::array<std::vector<int>, 3> block;
  for (int a = 0; a < 3; ++a) {
    block[a].assign(std::size_t(box.global[a]), 0);
    const bool weighted = weights[a].size() == std::size_t(box.global[a]);
    for (int r = 0; r < dims[a]; ++r) {
      const Extent e = weighted ? weighted_extent(weights[a], dims[a], r)
                                : block_extent(box.global[a], dims[a], r);
      for (int i = e.offset; i < e.offset + e.count; ++i) block[a][std::size_t(i)] = r;
    }
  }
  const std::size_t blocks = static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]) *
                             static_cast<std::size_t>(dims[2]);
  std::vector<double> work(blocks, 0.0);
  for (int z = 1; z <= box.n[2]; ++z)
    for (int y = 1; y <= box.n[1]; ++y)
      for (int x = 1; x <= box.n[0]; ++x) {
        const bool c = !d.empty() && d[std::size_t(box.index(x, y, z))] < 1.0f;
        const std::size_t b =
            std::size_t(block[0][std::size_t(box.offset[0] + x - 1)]) +
            std::size_t(dims[0]) *
                (std::size_t(block[1][std::size_t(box.offset[1] + y - 1)]) +
                 std::size_t(dims[1]) * std::size_t(block[2][std::size_t(box.offset[2] + z - 1)]));
        work[b] += weighted_work(1, c ? 1 : 0, covered_cell_weight);
      }
  MPI_Allreduce(MPI_IN_PLACE, work.data(), int(work.size()), MPI_DOUBLE, MPI_SUM, comm);
  double most = 0, total = 0;
  for (double w : work) {
    most = std::max(most, w);
    total += w;
  }
  return most / (total / double(work.size()));
}

LayoutChoice restart_layout(const FluidParams& fluid, const CheckpointWork& at, int fluid_ranks) {
  const bool same_ranks = at.fluid_ranks == fluid_ranks;
  if (fluid.decomposition != DecompositionKind::balanced) {
    const bool was_regular = at.layout[0].empty() && at.layout[1].empty() && at.layout[2].empty();
    return LayoutChoice{{}, "regular", same_ranks && was_regular};
  }
  if (same_ranks && at.imbalance <= fluid.rebalance_above)
    return LayoutChoice{at.layout,
                        fmt::format("kept from the checkpoint (load imbalance {:.3f} measured "
                                    "there, at most fluid.rebalance_above = {})",
                                    at.imbalance, fluid.rebalance_above),
                        true};
  const std::string reason =
      !same_ranks
          ? fmt::format("the checkpoint was written by {} fluid ranks", at.fluid_ranks)
          : fmt::format("load imbalance {:.3f} measured there, above fluid.rebalance_above = {}",
                        at.imbalance, fluid.rebalance_above);
  return LayoutChoice{at.measured,
                      "rebalanced by the work measured at the checkpoint (" + reason + ")", false};
}

}  // namespace lbdem
