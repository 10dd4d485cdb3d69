#include <gtest/gtest.h>

#include <cmath>

#include "fluid_app/output/field_file.hpp"
#include "output_test_support.hpp"

namespace lbdem {
namespace {

UnitConverter test_units() {
  return UnitConverter::from_tau(0.002, 0.8, 1e-6, 998.0);
}

// Writes one block with the MPI-IO driver, reads it back with the serial C API and compares
// every sample with the SI conversion of the synthetic state.
TEST(FieldFile, RoundTripOfStridedVolumeAndSliceInSiUnits) {
  test::ScratchDir dir("lbdem_field_file");
  FieldBlock box{{7, 5, 4}, {0, 0, 0}, {7, 5, 4}};
  const MacroFields f = test::test_fields(box);
  const UnitConverter units = test_units();
  FieldSlice slice;
  slice.axis = 0;
  slice.index = 3;
  slice.name = "slice_x3";
  const std::vector<FieldView> views{volume_view(box.global, 2), slice_view(box.global, 1, slice)};
  const std::string file = dir.file("f.h5");
  write_field_file(file, MPI_COMM_SELF, views, {true, true, true, true}, f, units, 42, 0.125);

  EXPECT_DOUBLE_EQ(test::read_double_attribute(file, "/", "time"), 0.125);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file, "/", "dx"), 0.002);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file, "/volume", "spacing_x"), 0.004);
  EXPECT_DOUBLE_EQ(test::read_double_attribute(file, "/slice_x3", "origin_x"), 3.5 * 0.002);

  const auto vel = test::read_dataset(file, "/volume/velocity");
  ASSERT_EQ(vel.dims, (std::vector<hsize_t>{2, 3, 4, 3}));  // z y x comp
  const auto rho = test::read_dataset(file, "/volume/density");
  const auto p = test::read_dataset(file, "/volume/pressure");
  ASSERT_EQ(rho.dims, (std::vector<hsize_t>{2, 3, 4}));
  std::size_t s = 0;
  for (int k = 0; k < 4; k += 2)
    for (int j = 0; j < 5; j += 2)
      for (int i = 0; i < 7; i += 2, ++s) {
        const double r = test::test_rho(i, j, k);
        EXPECT_DOUBLE_EQ(rho.values[s], r * 998.0);
        EXPECT_NEAR(p.values[s], (r - 1.0) / 3.0 * units.pressure(), 1e-12);
        for (int d = 0; d < 3; ++d)
          EXPECT_DOUBLE_EQ(vel.values[3 * s + d], test::test_u(i, j, k, d) * units.velocity());
      }

  const auto sl = test::read_dataset(file, "/slice_x3/density");
  ASSERT_EQ(sl.dims, (std::vector<hsize_t>{4, 5, 1}));
  EXPECT_DOUBLE_EQ(sl.values[2 * 5 + 4], test::test_rho(3, 4, 2) * 998.0);
}

TEST(FieldFile, FloatFilesHoldOnlyTheRequestedQuantities) {
  test::ScratchDir dir("lbdem_field_file_float");
  FieldBlock box{{3, 3, 3}, {0, 0, 0}, {3, 3, 3}};
  const MacroFields f = test::test_fields(box);
  const std::string file = dir.file("f.h5");
  write_field_file(file, MPI_COMM_SELF, {volume_view(box.global, 1)}, {false, false, true, false},
                   f, test_units(), 0, 0.0);
  EXPECT_TRUE(test::read_dataset(file, "/volume/velocity").values.empty());
  EXPECT_TRUE(test::read_dataset(file, "/volume/density").values.empty());
  const auto p = test::read_dataset(file, "/volume/pressure");
  ASSERT_EQ(p.values.size(), 27u);
  const double expect = (test::test_rho(2, 1, 0) - 1.0) / 3.0 * test_units().pressure();
  EXPECT_NEAR(p.values[1 * 3 + 2], expect, 1e-6 * std::abs(expect));  // float32 precision
}

}  // namespace
}  // namespace lbdem
