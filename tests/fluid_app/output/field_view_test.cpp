#include <gtest/gtest.h>

#include <vector>

#include "fluid_app/output/field_view.hpp"

namespace lbdem {
namespace {

TEST(FieldView, VolumeStrideCountsIncludeTheLastPartialSample) {
  const FieldView v = volume_view({10, 7, 1}, 3);
  EXPECT_EQ(v.axes[0].count, 4);  // nodes 0 3 6 9
  EXPECT_EQ(v.axes[1].count, 3);  // nodes 0 3 6
  EXPECT_EQ(v.axes[2].count, 1);
  EXPECT_EQ(v.samples(), 12);
}

TEST(FieldView, SliceIsOneNodeThickAtItsIndex) {
  FieldSlice s;
  s.axis = 1;
  s.index = 5;
  s.name = "slice_y5";
  const FieldView v = slice_view({8, 8, 8}, 2, s);
  EXPECT_EQ(v.name, "slice_y5");
  EXPECT_EQ(v.axes[1].start, 5);
  EXPECT_EQ(v.axes[1].count, 1);
  EXPECT_EQ(v.axes[0].count, 4);
  EXPECT_EQ(v.axes[2].count, 4);
}

// Every sample of a view must belong to exactly one block of any decomposition.
TEST(FieldView, BlocksOfAnUnevenSplitCoverEverySampleOnce) {
  const std::array<int, 3> global{11, 5, 9};
  const std::vector<std::vector<int>> cuts{{0, 4, 7, 11}, {0, 5}, {0, 2, 3, 9}};
  FieldSlice slice;
  slice.axis = 2;
  slice.index = 2;
  for (const FieldView& view : {volume_view(global, 1), volume_view(global, 2),
                                volume_view(global, 4), slice_view(global, 3, slice)}) {
    std::vector<int> hits(static_cast<std::size_t>(view.samples()), 0);
    for (std::size_t a = 0; a + 1 < cuts[0].size(); ++a)
      for (std::size_t b = 0; b + 1 < cuts[1].size(); ++b)
        for (std::size_t c = 0; c + 1 < cuts[2].size(); ++c) {
          FieldBlock box;
          box.global = global;
          box.lo = {cuts[0][a], cuts[1][b], cuts[2][c]};
          box.n = {cuts[0][a + 1] - cuts[0][a], cuts[1][b + 1] - cuts[1][b],
                   cuts[2][c + 1] - cuts[2][c]};
          const LocalSelection sel = local_selection(view, box);
          for (int mk = sel.first[2]; mk < sel.first[2] + sel.count[2]; ++mk)
            for (int mj = sel.first[1]; mj < sel.first[1] + sel.count[1]; ++mj)
              for (int mi = sel.first[0]; mi < sel.first[0] + sel.count[0]; ++mi) {
                // The sample's node must lie inside this block.
                for (int d = 0; d < 3; ++d) {
                  const int m = d == 0 ? mi : d == 1 ? mj : mk;
                  const int g = view.axes[d].start + m * view.axes[d].stride;
                  ASSERT_GE(g, box.lo[d]);
                  ASSERT_LT(g, box.lo[d] + box.n[d]);
                }
                ++hits[(std::size_t(mk) * view.axes[1].count + mj) * view.axes[0].count + mi];
              }
        }
    for (std::size_t s = 0; s < hits.size(); ++s)
      ASSERT_EQ(hits[s], 1) << view.name << " sample " << s;
  }
}

}  // namespace
}  // namespace lbdem
