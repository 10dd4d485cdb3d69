// STL reading (ASCII and binary) and the closed/oriented mesh check.
#include <gtest/gtest.h>

#include <fstream>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/mesh_check.hpp"
#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/stl_io.hpp"
#include "temp_file.hpp"

namespace lbdem {
namespace {

std::string error_of(const TriangleMesh& m, const std::string& file) {
  try {
    check_closed_oriented(m, file);
  } catch (const ShapeError& e) {
    return e.what();
  }
  return "";
}

TEST(StlIo, AsciiRoundTripRecoversConnectivity) {
  test::TempFile f("cube_ascii.stl");
  const TriangleMesh cube = box_mesh({1.0, 2.0, 3.0});
  write_stl_ascii(f.str(), cube, "cube");
  const TriangleMesh back = read_stl(f.str());
  EXPECT_EQ(back.triangles.size(), 12u);
  EXPECT_EQ(back.vertices.size(), 8u);  // shared vertices merged
  EXPECT_DOUBLE_EQ(signed_volume(back), 6.0);
  EXPECT_NO_THROW(check_closed_oriented(back, f.str()));
}

TEST(StlIo, BinaryRoundTripRecoversConnectivity) {
  test::TempFile f("sphere_bin.stl");
  const TriangleMesh ico = icosphere_mesh(0.5, 2);
  write_stl_binary(f.str(), ico);
  const TriangleMesh back = read_stl(f.str());
  EXPECT_EQ(back.triangles.size(), 320u);
  EXPECT_EQ(back.vertices.size(), ico.vertices.size());
  // Binary STL stores float: the volume matches to single precision.
  EXPECT_NEAR(signed_volume(back), signed_volume(ico), 1e-6);
  EXPECT_NO_THROW(check_closed_oriented(back, f.str()));
}

TEST(StlIo, BinaryWhoseHeaderStartsWithSolidIsReadAsBinary) {
  test::TempFile f("solid_header.stl");
  write_stl_binary(f.str(), box_mesh({1, 1, 1}));
  {
    std::fstream io(f.str(), std::ios::in | std::ios::out | std::ios::binary);
    io.write("solid cube", 10);
  }
  EXPECT_EQ(read_stl(f.str()).triangles.size(), 12u);
}

TEST(StlIo, MalformedFilesNameFileAndLine) {
  test::TempFile f("bad.stl");
  {
    std::ofstream o(f.str());
    o << "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0\n";
  }
  try {
    read_stl(f.str());
    FAIL() << "expected a ShapeError";
  } catch (const ShapeError& e) {
    EXPECT_NE(std::string(e.what()).find(f.str() + ":5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_stl(f.str() + ".missing"), ShapeError);
  {
    std::ofstream o(f.str());
    o << "not an stl at all";
  }
  EXPECT_THROW(read_stl(f.str()), ShapeError);
}

TEST(MeshCheck, OpenMeshReportsEdgeCountAndPosition) {
  TriangleMesh m = box_mesh({1, 1, 1});
  m.triangles.pop_back();  // one triangle missing: its 3 edges are open
  const std::string msg = error_of(m, "cube.stl");
  EXPECT_EQ(msg.rfind("cube.stl: 3 open edges", 0), 0u) << msg;
  EXPECT_NE(msg.find("first at ("), std::string::npos) << msg;
}

TEST(MeshCheck, FlippedTriangleIsInconsistentlyOriented) {
  TriangleMesh m = icosphere_mesh(1.0, 1);
  std::swap(m.triangles[7][1], m.triangles[7][2]);
  const std::string msg = error_of(m, "ball.stl");
  EXPECT_EQ(msg.rfind("ball.stl: 3 inconsistently oriented edges", 0), 0u) << msg;
}

TEST(MeshCheck, InsideOutMeshIsRejected) {
  TriangleMesh m = box_mesh({1, 1, 1});
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  const std::string msg = error_of(m, "cube.stl");
  EXPECT_NE(msg.find("not positive"), std::string::npos) << msg;
}

TEST(MeshCheck, DegenerateTriangleIsRejected) {
  TriangleMesh m = box_mesh({1, 1, 1});
  m.triangles[0][1] = m.triangles[0][0];
  EXPECT_NE(error_of(m, "cube.stl").find("degenerate"), std::string::npos);
}

TEST(MeshCheck, PrimitivesAreClosedAndOriented) {
  EXPECT_EQ(error_of(box_mesh({1, 2, 3}), "box"), "");
  EXPECT_EQ(error_of(icosphere_mesh(1, 3), "ico"), "");
  EXPECT_EQ(error_of(octahedron_mesh(1), "octa"), "");
  EXPECT_NEAR(signed_volume(octahedron_mesh(1)), 4.0 / 3.0, 1e-14);
}

}  // namespace
}  // namespace lbdem
