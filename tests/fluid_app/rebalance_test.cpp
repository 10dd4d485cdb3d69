// Rebalancing at a restart (fluid_app/parallel/rebalance.hpp): the work a checkpoint measures
// and the layout a restart takes from it.
#include <gtest/gtest.h>
#include <mpi.h>

#include "fluid_app/parallel/rebalance.hpp"

namespace lbdem {
namespace {

CheckpointWork recorded(double imbalance, int ranks) {
  CheckpointWork w;
  w.measured = {std::vector<double>{1, 2}, std::vector<double>{3, 4}, std::vector<double>{5, 6}};
  w.layout = {std::vector<double>{7, 8}, std::vector<double>{9, 10}, std::vector<double>{11, 12}};
  w.imbalance = imbalance;
  w.fluid_ranks = ranks;
  return w;
}

TEST(RestartLayout, BalancedKeepsTheCheckpointsCutsUpToTheThresholdThenCutsByTheMeasuredWork) {
  FluidParams f;
  f.decomposition = DecompositionKind::balanced;
  f.rebalance_above = 1.1;
  const LayoutChoice kept = restart_layout(f, recorded(1.1, 4), 4);
  EXPECT_EQ(kept.weights, recorded(1.1, 4).layout);
  EXPECT_TRUE(kept.same_as_checkpoint);
  EXPECT_NE(kept.why.find("kept from the checkpoint"), std::string::npos) << kept.why;
  const LayoutChoice recut = restart_layout(f, recorded(1.3, 4), 4);
  EXPECT_EQ(recut.weights, recorded(1.3, 4).measured);
  EXPECT_FALSE(recut.same_as_checkpoint);
  EXPECT_NE(recut.why.find("above fluid.rebalance_above"), std::string::npos) << recut.why;
  // Another rank count: the old cuts do not apply.
  const LayoutChoice other = restart_layout(f, recorded(1.0, 4), 8);
  EXPECT_EQ(other.weights, recorded(1.0, 4).measured);
  EXPECT_FALSE(other.same_as_checkpoint);
  EXPECT_NE(other.why.find("written by 4 fluid ranks"), std::string::npos) << other.why;
}

TEST(RestartLayout, RegularIsTheCheckpointsLayoutOnlyIfThatWasRegularOnAsManyRanks) {
  FluidParams f;
  const LayoutChoice from_balanced = restart_layout(f, recorded(2.0, 4), 4);
  EXPECT_TRUE(from_balanced.weights[0].empty());
  EXPECT_FALSE(from_balanced.same_as_checkpoint);
  CheckpointWork regular = recorded(2.0, 4);
  regular.layout = {};
  EXPECT_TRUE(restart_layout(f, regular, 4).same_as_checkpoint);
  EXPECT_FALSE(restart_layout(f, regular, 5).same_as_checkpoint);
}

TEST(MeasureWork, SlicesCountCoveredCellsAtTheirWeight) {
  LocalBox box;
  box.n = {4, 3, 2};
  box.global = {4, 3, 2};
  std::vector<float> d(std::size_t(box.cells_with_ghosts()), 1.0f);
  d[std::size_t(box.index(1, 1, 1))] = 0.0f;  // an interior cell
  d[std::size_t(box.index(4, 3, 1))] = 0.5f;  // a band cell
  const CheckpointWork w = measure_work(box, d, 10.0, MPI_COMM_SELF);
  // x slice 0: 3 x 2 cells, one covered: 6 + 9.
  EXPECT_DOUBLE_EQ(w.measured[0][0], 15.0);
  EXPECT_DOUBLE_EQ(w.measured[0][3], 15.0);
  EXPECT_DOUBLE_EQ(w.measured[0][1], 6.0);
  EXPECT_DOUBLE_EQ(w.measured[2][0], 12.0 + 18.0);
  EXPECT_DOUBLE_EQ(w.measured[2][1], 12.0);
  EXPECT_DOUBLE_EQ(w.imbalance, 1.0);  // one rank
  EXPECT_EQ(w.fluid_ranks, 1);
  // Without bodies every cell counts 1.
  EXPECT_DOUBLE_EQ(measure_work(box, {}, 10.0, MPI_COMM_SELF).measured[1][2], 8.0);
}

TEST(ImbalanceOfCuts, CountsTheBlocksANewCutWouldHoldBeforeAnythingMoves) {
  LocalBox box;
  box.n = {4, 1, 1};
  box.global = {4, 1, 1};
  std::vector<float> d(std::size_t(box.cells_with_ghosts()), 1.0f);
  d[std::size_t(box.index(1, 1, 1))] = 0.0f;  // global cell 0 covered: work 10, the rest 1
  const std::array<int, 3> dims{2, 1, 1};
  // Equal blocks [0, 1] and [2, 3]: 11 and 2 against a mean of 6.5.
  EXPECT_DOUBLE_EQ(imbalance_of_cuts(box, d, 10.0, {}, dims, MPI_COMM_SELF), 11.0 / 6.5);
  // Cut by the slices' work (10, 1, 1, 1): [0] and [1, 3], 10 and 3.
  const SliceWeights w = {std::vector<double>{10, 1, 1, 1}, {}, {}};
  EXPECT_DOUBLE_EQ(imbalance_of_cuts(box, d, 10.0, w, dims, MPI_COMM_SELF), 10.0 / 6.5);
  // Without bodies every cell counts 1: 1 and 3 cells.
  EXPECT_DOUBLE_EQ(imbalance_of_cuts(box, {}, 10.0, w, dims, MPI_COMM_SELF), 1.5);
}

}  // namespace
}  // namespace lbdem
