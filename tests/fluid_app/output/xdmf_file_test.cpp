#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fluid_app/output/xdmf_file.hpp"
#include "output_test_support.hpp"

namespace lbdem {
namespace {

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(Xdmf, TemporalCollectionListsEveryStepWithZyxGeometry) {
  FieldView v = volume_view({8, 6, 4}, 2);
  const std::string x =
      xdmf_text(v, {true, false, true, false}, 0.5, {{0.0, "a_000000.h5"}, {0.25, "a_000001.h5"}});
  EXPECT_EQ(count(x, "CollectionType=\"Temporal\""), 1);
  EXPECT_EQ(count(x, "GridType=\"Uniform\""), 2);
  EXPECT_NE(x.find("<Time Value=\"0.25\"/>"), std::string::npos);
  // 4 x 3 x 2 samples, written slowest first.
  EXPECT_NE(x.find("TopologyType=\"3DCoRectMesh\" Dimensions=\"2 3 4\""), std::string::npos);
  // Origin at the first node's cell centre, spacing stride * dx = 1.
  EXPECT_NE(x.find(">0.25 0.25 0.25</DataItem>"), std::string::npos);
  EXPECT_NE(x.find(">1 1 1</DataItem>"), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"2 3 4 3\" NumberType=\"Float\" Precision=\"4\""),
            std::string::npos);
  EXPECT_NE(x.find("a_000001.h5:/volume/pressure"), std::string::npos);
  EXPECT_EQ(x.find("density"), std::string::npos);
}

TEST(Xdmf, SliceGeometryStartsAtTheSlicePlane) {
  FieldSlice s;
  s.axis = 2;
  s.index = 3;
  s.name = "slice_z3";
  const std::string x = xdmf_text(slice_view({4, 4, 8}, 1, s), {}, 1.0, {{1.0, "f.h5"}});
  EXPECT_NE(x.find("Dimensions=\"1 4 4\""), std::string::npos);
  EXPECT_NE(x.find(">3.5 0.5 0.5</DataItem>"), std::string::npos);  // z y x
  EXPECT_NE(x.find("f.h5:/slice_z3/velocity"), std::string::npos);
}

TEST(Xdmf, AtomicWriteReplacesTheFileCompletely) {
  test::ScratchDir dir("lbdem_xdmf");
  const std::string path = dir.file("a.xdmf");
  write_file_atomically(path, "first version, longer than the second");
  write_file_atomically(path, "second");
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), "second");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

}  // namespace
}  // namespace lbdem
