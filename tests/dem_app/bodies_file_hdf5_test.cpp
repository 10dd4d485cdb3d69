// Bodies from an HDF5 file (coupler_lib/scene/bodies_file.hpp): the same bodies as the same file
// in CSV, the same checks, and a malformed file refused naming the file, the body index, the
// dataset and what was expected.
#include <gtest/gtest.h>
#include <hdf5.h>

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

// One dataset to write: numbers (rows x width, width 0 for 1-D) or strings.
struct Set {
  std::string name;
  std::vector<double> numbers;
  size_t width = 0;
  std::vector<std::string> strings;
  bool utf8 = false;  // as h5py writes strings
};

Set numbers(const std::string& name, std::vector<double> v, size_t width) {
  Set s;
  s.name = name;
  s.numbers = std::move(v);
  s.width = width;
  return s;
}

Set strings(const std::string& name, std::vector<std::string> v, bool utf8 = false) {
  Set s;
  s.name = name;
  s.strings = std::move(v);
  s.utf8 = utf8;
  return s;
}

// Writes the datasets at the root of a fresh file in the temporary folder; returns its path.
std::string write_h5(const std::string& name, const std::vector<Set>& sets) {
  const auto path =
      (std::filesystem::temp_directory_path() / ("lbdem_bodies_file_" + name)).string();
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  for (const auto& s : sets) {
    if (!s.strings.empty()) {
      const hsize_t n = s.strings.size();
      const hid_t type = H5Tcopy(H5T_C_S1);
      H5Tset_size(type, H5T_VARIABLE);
      if (s.utf8) H5Tset_cset(type, H5T_CSET_UTF8);
      const hid_t space = H5Screate_simple(1, &n, nullptr);
      const hid_t set =
          H5Dcreate2(file, s.name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      std::vector<const char*> p;
      for (const auto& t : s.strings) p.push_back(t.c_str());
      H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.data());
      H5Dclose(set);
      H5Sclose(space);
      H5Tclose(type);
      continue;
    }
    const hsize_t dims[2] = {s.width ? s.numbers.size() / s.width : s.numbers.size(), s.width};
    const hid_t space = H5Screate_simple(s.width ? 2 : 1, dims, nullptr);
    const hid_t set = H5Dcreate2(file, s.name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, s.numbers.data());
    H5Dclose(set);
    H5Sclose(space);
  }
  H5Fclose(file);
  return path;
}

using test::error_of;
using test::parse;

TEST(BodiesFileHdf5, SameBodiesAsTheCsvFile) {
  const auto h5 = write_h5(
      "full.h5", {numbers("position", {0.02, 0.03, 0.04, 0.06, 0.07, 0.08}, 3),
                  numbers("orientation", {2, 0, 0, 0, 1, 0, 0, 1}, 4),
                  numbers("velocity", {0.1, 0.2, 0.3, 0, 0, -0.5}, 3),
                  numbers("angular_velocity", {1, 2, 3, 0, 0, 0}, 3),
                  numbers("density", {2500, 1200}, 0), strings("shape", {"cube", "ball"}, true)});
  const auto csv = std::filesystem::temp_directory_path() / "lbdem_bodies_file_full_h5.csv";
  std::ofstream(csv) << "x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,density,shape\n"
                        "0.02,0.03,0.04,2,0,0,0,0.1,0.2,0.3,1,2,3,2500,cube\n"
                        "0.06,0.07,0.08,1,0,0,1,0,0,-0.5,0,0,0,1200,ball\n";
  const Scene a = parse(kBodiesFileBase + "bodies:\n  - {file: " + h5 + "}\n");
  const Scene b = parse(kBodiesFileBase + "bodies:\n  - {file: " + csv.string() + "}\n");
  ASSERT_EQ(a.bodies.size(), 2u);
  ASSERT_EQ(b.bodies.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(a.bodies[i].shape, b.bodies[i].shape);
    EXPECT_EQ(a.bodies[i].position, b.bodies[i].position);
    EXPECT_EQ(a.bodies[i].orientation, b.bodies[i].orientation);
    EXPECT_EQ(a.bodies[i].velocity, b.bodies[i].velocity);
    EXPECT_EQ(a.bodies[i].angular_velocity, b.bodies[i].angular_velocity);
    EXPECT_EQ(a.bodies[i].density, b.bodies[i].density);
  }
  EXPECT_EQ(a.bodies[0].shape, 1);
  EXPECT_EQ(a.bodies[0].orientation, (std::array<double, 4>{1, 0, 0, 0}));  // normalised
  EXPECT_EQ(error_of(kBodiesFileBase + "bodies:\n  - {file: " + h5 + "}\n"), "");
}

TEST(BodiesFileHdf5, FormatKeyAndEntryKeys) {
  // Position only, shape and density from the entry; `format: hdf5` whatever the extension.
  const auto f = write_h5("positions.dat", {numbers("position", {0.05, 0.05, 0.05}, 3)});
  const Scene s = parse(kBodiesFileBase + "bodies:\n  - {file: " + f +
                        ", format: hdf5, shape: ball, density: 3000}\n");
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].density, 3000);
  EXPECT_EQ(s.bodies[0].shape, 0);
  // The same file read as CSV (the default for .dat) is refused as CSV.
  EXPECT_NE(error_of(kBodiesFileBase + "bodies:\n  - {file: " + f + ", shape: ball, density: 1}\n"),
            "");
  EXPECT_NE(error_of(kBodiesFileBase + "bodies:\n  - {file: " + f + ", format: xml, shape: ball}\n")
                .find("bodies[0].format: expected one of {csv, hdf5}"),
            std::string::npos);
}

TEST(BodiesFileHdf5, SameChecksAsInlineBodies) {
  const auto overlap =
      write_h5("overlap.h5", {numbers("position", {0.05, 0.05, 0.05, 0.055, 0.05, 0.05}, 3)});
  EXPECT_NE(error_of(kBodiesFileBase + "bodies:\n  - {file: " + overlap +
                     ", shape: ball, density: 2500}\n")
                .find("overlap"),
            std::string::npos);
  const auto outside = write_h5("outside.h5", {numbers("position", {0.099, 0.05, 0.05}, 3)});
  EXPECT_NE(error_of(kBodiesFileBase + "bodies:\n  - {file: " + outside +
                     ", shape: ball, density: 2500}\n"),
            "");
}

TEST(BodiesFileHdf5, MalformedFilesNameBodyDatasetAndWhatWasExpected) {
  const std::vector<double> one = {0.05, 0.05, 0.05};
  struct Case {
    std::string name;
    std::vector<Set> sets;
    std::string entry, expect;
  };
  const std::vector<Case> cases = {
      {"no_position.h5",
       {numbers("velocity", {0, 0, 0}, 3)},
       "shape: ball, density: 1",
       ": missing dataset 'position'"},
      {"unknown.h5",
       {numbers("position", one, 3), numbers("positions", one, 3)},
       "shape: ball, density: 1",
       "unknown dataset 'positions' (did you mean 'position'?)"},
      {"wide.h5",
       {numbers("position", {0.05, 0.05, 0.05, 0}, 4)},
       "shape: ball, density: 1",
       "dataset 'position': expected 1 x 3 numbers"},
      {"rows.h5",
       {numbers("position", one, 3), numbers("velocity", {0, 0, 0, 0, 0, 0}, 3)},
       "shape: ball, density: 1",
       "dataset 'velocity': expected 1 x 3 numbers"},
      {"nan.h5",
       {numbers("position", {0.05, NAN, 0.05}, 3)},
       "shape: ball, density: 1",
       ": body 0: dataset 'position': expected finite numbers"},
      {"zero_q.h5",
       {numbers("position", one, 3), numbers("orientation", {0, 0, 0, 0}, 4)},
       "shape: ball, density: 1",
       ": body 0: dataset 'orientation': the quaternion must not be zero"},
      {"both_shape.h5",
       {numbers("position", one, 3), strings("shape", {"ball"})},
       "shape: ball, density: 1",
       "'shape' is both a dataset and a key of the entry"},
      {"no_density.h5", {numbers("position", one, 3)}, "shape: ball", "no 'density'"},
      {"bad_shape.h5",
       {numbers("position", one, 3), strings("shape", {"cub"})},
       "density: 1",
       ": body 0: dataset 'shape': no shape named 'cub'"},
      {"shape_numbers.h5",
       {numbers("position", one, 3), numbers("shape", {1}, 0)},
       "density: 1",
       "dataset 'shape': expected 1 strings"},
      {"bad_density.h5",
       {numbers("position", one, 3), numbers("density", {-3}, 0)},
       "shape: ball",
       ": body 0: dataset 'density': expected a density > 0"},
  };
  for (const auto& c : cases) {
    const auto f = write_h5(c.name, c.sets);
    const auto m = error_of(kBodiesFileBase + "bodies:\n  - {file: " + f + ", " + c.entry + "}\n");
    EXPECT_NE(m.find(f), std::string::npos) << c.name << ": " << m;
    EXPECT_NE(m.find(c.expect), std::string::npos) << c.name << ": " << m;
    EXPECT_NE(m.find("(bodies file of t.yaml:10: bodies[0].file)"), std::string::npos)
        << c.name << ": " << m;
  }
  // Not an HDF5 file at all.
  const auto text = std::filesystem::temp_directory_path() / "lbdem_bodies_file_text.h5";
  std::ofstream(text) << "x,y,z\n0.05,0.05,0.05\n";
  const auto m =
      error_of(kBodiesFileBase + "bodies:\n  - {file: " + text.string() + ", shape: ball}\n");
  EXPECT_NE(m.find("cannot open it as an HDF5 file"), std::string::npos) << m;
}

}  // namespace
}  // namespace lbdem
