// Bodies from a CSV file (coupler_lib/scene/bodies_file.hpp): read as inline bodies are, checked
// as inline bodies are (overlaps, box), and a malformed file is refused with file:line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/setup/dem_setup.hpp"
#include "dem_scene_text.hpp"

namespace lbdem {
namespace {

using test::kBodiesFileBase;

// Writes `text` to a fresh file in the temporary folder; returns its absolute path.
std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("lbdem_bodies_file_" + name);
  std::ofstream(path) << text;
  return path.string();
}

using test::error_of;
using test::parse;

TEST(BodiesFile, ReadsEveryColumnAndTheEntryKeys) {
  const auto f = write_file("full.csv",
                            "# written by a test\n"
                            "x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n"
                            "0.02,0.03,0.04,2,0,0,0,0.1,0.2,0.3,1,2,3\n"
                            "\n"
                            "0.06,0.07,0.08,1,0,0,1,0,0,-0.5,0,0,0\n");
  const Scene s =
      parse(kBodiesFileBase + "bodies:\n  - {file: " + f + ", shape: cube, density: 2500}\n");
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].shape, 1);
  EXPECT_EQ(s.bodies[0].position, (std::array<double, 3>{0.02, 0.03, 0.04}));
  EXPECT_EQ(s.bodies[0].orientation, (std::array<double, 4>{1, 0, 0, 0}));  // normalised
  EXPECT_EQ(s.bodies[0].velocity, (std::array<double, 3>{0.1, 0.2, 0.3}));
  EXPECT_EQ(s.bodies[0].angular_velocity, (std::array<double, 3>{1, 2, 3}));
  EXPECT_NEAR(s.bodies[1].orientation[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(s.bodies[1].orientation[3], std::sqrt(0.5), 1e-15);
  EXPECT_EQ(s.bodies[1].density, 2500);
  EXPECT_EQ(
      error_of(kBodiesFileBase + "bodies:\n  - {file: " + f + ", shape: cube, density: 2500}\n"),
      "");
}

TEST(BodiesFile, ShapeAndDensityAsColumnsMixWithInlineBodies) {
  const auto f = write_file("columns.csv", "shape,density,z,y,x\nball,1200,0.05,0.05,0.05\n");
  const Scene s = parse(kBodiesFileBase + "bodies:\n  - {file: " + f +
                        "}\n  - {shape: cube, position: [0.02, 0.02, 0.02], density: 3000}\n");
  ASSERT_EQ(s.bodies.size(), 2u);
  EXPECT_EQ(s.bodies[0].shape, 0);
  EXPECT_EQ(s.bodies[0].density, 1200);
  EXPECT_EQ(s.bodies[1].shape, 1);
}

TEST(BodiesFile, SameValidationAsInlineBodies) {
  const auto overlap = write_file("overlap.csv", "x,y,z\n0.05,0.05,0.05\n0.055,0.05,0.05\n");
  EXPECT_NE(error_of(kBodiesFileBase + "bodies:\n  - {file: " + overlap +
                     ", shape: ball, density: 2500}\n")
                .find("overlap"),
            std::string::npos);
  const auto outside = write_file("outside.csv", "x,y,z\n0.099,0.05,0.05\n");
  EXPECT_NE(error_of(kBodiesFileBase + "bodies:\n  - {file: " + outside +
                     ", shape: ball, density: 2500}\n"),
            "");
}

// Each malformed file: the message names the file and line and what was expected.
TEST(BodiesFile, MalformedFilesAreRefusedWithFileAndLine) {
  struct Case {
    std::string name, text, entry, expect;
  };
  const std::vector<Case> cases = {
      {"short_row.csv", "x,y,z\n0.05,0.05\n", "shape: ball, density: 1", ":2: expected 3 comma"},
      {"bad_number.csv", "x,y,z\n# c\n0.05,abc,0.05\n", "shape: ball, density: 1",
       ":3: column 'y': expected a finite number, got 'abc'"},
      {"unknown.csv", "x,y,z,vv\n", "shape: ball, density: 1", ":1: unknown column 'vv'"},
      {"missing.csv", "x,y\n", "shape: ball, density: 1", ":1: missing column 'z'"},
      {"partial_q.csv", "x,y,z,qw\n", "shape: ball, density: 1", "qw, qx, qy, qz come together"},
      {"zero_q.csv", "x,y,z,qw,qx,qy,qz\n1,1,1,0,0,0,0\n", "shape: ball, density: 1",
       ":2: columns qw qx qy qz: the quaternion must not be zero"},
      {"both_shape.csv", "x,y,z,shape\n", "shape: ball, density: 1", "both a column and a key"},
      {"no_density.csv", "x,y,z\n", "shape: ball", "no 'density'"},
      {"bad_shape.csv", "x,y,z,shape\n0.05,0.05,0.05,cub\n", "density: 1",
       ":2: column 'shape': no shape named 'cub'"},
      {"bad_density.csv", "x,y,z,density\n0.05,0.05,0.05,-3\n", "shape: ball",
       ":2: column 'density': expected a density > 0"},
      {"empty.csv", "# nothing\n", "shape: ball, density: 1", "no header line"},
      {"no_rows.csv", "x,y,z\n", "shape: ball, density: 1", "a header but no bodies"},
  };
  for (const auto& c : cases) {
    const auto f = write_file(c.name, c.text);
    const auto m = error_of(kBodiesFileBase + "bodies:\n  - {file: " + f + ", " + c.entry + "}\n");
    EXPECT_NE(m.find(f), std::string::npos) << c.name << ": " << m;
    EXPECT_NE(m.find(c.expect), std::string::npos) << c.name << ": " << m;
  }
  const auto m =
      error_of(kBodiesFileBase + "bodies:\n  - {file: /nonexistent/bodies.csv, shape: ball}\n");
  EXPECT_NE(m.find("t.yaml:10: bodies[0].file: cannot open"), std::string::npos) << m;
}

}  // namespace
}  // namespace lbdem
