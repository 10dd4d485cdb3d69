// Body output gathered in id ranges (dem_app/output/output_chunks.hpp): the pieces, concatenated on
// rank 0, are every rank's items ordered by id, equal ids in rank order, for pieces smaller
// than the id range (the production piece is 65536 ids; here 7). Run on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "dem_app/output/output_chunks.hpp"

namespace lbdem {
namespace {

TEST(OutputChunks, PiecesConcatenateToTheIdOrder) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  // Rank r holds ids r, r + P, ... below 50 (given in descending order), and every rank id 20.
  std::vector<BodyLoad> mine;
  for (int id = 49; id >= 0; --id)
    if (id % size == rank || id == 20) {
      BodyLoad l;
      l.id = id;
      l.f[0] = rank;
      mine.push_back(l);
    }
  const std::vector<BodyLoad> sorted = sorted_by_id(std::span<const BodyLoad>(mine));
  const std::int64_t end = id_end(sorted, MPI_COMM_WORLD);
  EXPECT_EQ(end, 50);
  std::vector<BodyLoad> all;
  for (std::int64_t lo = 0; lo < end; lo += 7) {
    const auto piece =
        gather_id_range(sorted, lo, std::min<std::int64_t>(end, lo + 7), MPI_COMM_WORLD);
    all.insert(all.end(), piece.begin(), piece.end());
  }
  if (rank != 0) {
    EXPECT_TRUE(all.empty());
    return;
  }
  ASSERT_EQ(all.size(), static_cast<size_t>(49 + size));  // id 20 once per rank
  std::size_t k = 0;
  for (int id = 0; id < 50; ++id) {
    const int copies = id == 20 ? size : 1;
    for (int c = 0; c < copies; ++c, ++k) {
      EXPECT_EQ(all[k].id, id);
      EXPECT_EQ(all[k].f[0], id == 20 ? c : id % size);  // equal ids in rank order
    }
  }
}

}  // namespace
}  // namespace lbdem
