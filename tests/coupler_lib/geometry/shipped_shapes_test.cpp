// The files shipped under configs/shapes: every clump loads and has the sphere count its
// header states, and for one clump of each method the shape errors recomputed here agree
// with the header (the numbers in docs/user-guide.md); the STL files are closed and oriented.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "coupler_lib/geometry/clump_generator.hpp"
#include "coupler_lib/geometry/clump_io.hpp"
#include "coupler_lib/geometry/mass_properties.hpp"
#include "coupler_lib/geometry/mesh_check.hpp"
#include "coupler_lib/geometry/stl_io.hpp"
#include "coupler_lib/geometry/voxelize.hpp"

namespace lbdem {
namespace {

const std::filesystem::path kDir = std::filesystem::path(LBDEM_SOURCE_DIR) / "configs/shapes";

// "# key: value ..." header lines of a clump file.
std::map<std::string, std::string> header(const std::filesystem::path& p) {
  std::map<std::string, std::string> h;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# ", 0) != 0) continue;
    const auto colon = line.find(": ");
    if (colon != std::string::npos) h[line.substr(2, colon - 2)] = line.substr(colon + 2);
  }
  return h;
}

TEST(ShippedShapes, StlFilesAreClosedAndOriented) {
  for (const char* name : {"cube.stl", "sphere.stl"}) {
    const auto file = (kDir / name).string();
    const TriangleMesh m = read_stl(file);
    EXPECT_NO_THROW(check_closed_oriented(m, file));
  }
  EXPECT_NEAR(signed_volume(read_stl((kDir / "cube.stl").string())), 1.0, 1e-12);
}

TEST(ShippedShapes, ClumpsMatchTheirHeaders) {
  const SolidGeometry cube = SolidGeometry::cuboid({1, 1, 1});
  const SolidGeometry sphere = SolidGeometry::sphere(0.5);
  const TriangleMesh ico = read_stl((kDir / "sphere.stl").string());
  const SolidGeometry icosphere = SolidGeometry::mesh(ico);
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kDir)) {
    if (entry.path().extension() != ".clump") continue;
    const std::string name = entry.path().filename().string();
    const auto h = header(entry.path());
    const Clump c = read_clump(entry.path().string());
    ASSERT_TRUE(h.count("spheres")) << name;
    EXPECT_EQ(std::to_string(c.size()), h.at("spheres")) << name;
    // Recomputing the errors takes a while; do it for one clump of each method and source.
    if (name != "cube_489_surface.clump" && name != "cube_27_fill.clump" &&
        name != "sphere_stl_1.clump")
      continue;
    const SolidGeometry& solid = name.rfind("cube", 0) == 0         ? cube
                                 : name.rfind("sphere_stl", 0) == 0 ? icosphere
                                                                    : sphere;
    // The generator's lattice: 81 voxels across, 3 empty layers; clump in the shape frame.
    const Voxels v = voxelize(solid, 1.0 / 81, 3);
    const Eigen::Vector3d centroid = mass_properties(v).centroid;
    const ClumpQuality q = clump_quality(translated(c, -centroid), v);
    const double vol = std::stod(h.at("volume_error"));
    const double dev = std::stod(h.at("max_surface_deviation"));
    EXPECT_NEAR(q.volume_error, vol, 1e-4) << name;
    EXPECT_NEAR(q.max_deviation, dev, 1e-4) << name;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

}  // namespace
}  // namespace lbdem
