// Reads what `dem_app pour_small.yaml` wrote (directory in LBDEM_DEM_OUTPUT) and checks it:
// snapshots with every body, unit quaternions consistent with the axis vectors, bodies
// resting on the floor inside the periodic box, each body's surface placed at its pose, and an
// energy series where the pour has come (nearly) to rest with contacts.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string output_dir() {
  const char* d = std::getenv("LBDEM_DEM_OUTPUT");
  return d ? d : "";
}

std::vector<double> read_doubles(hid_t file, const std::string& path) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(set, 0) << path;
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  const auto n = static_cast<size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<double> v(n);
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(space);
  H5Dclose(set);
  return v;
}

TEST(DemOutput, SnapshotsHoldEveryBodyWithConsistentOrientation) {
  ASSERT_FALSE(output_dir().empty()) << "set LBDEM_DEM_OUTPUT";
  const std::string h5 = output_dir() + "/pour_small_bodies.h5";
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0) << h5;
  hsize_t groups = 0;
  H5Gget_num_objs(file, &groups);
  EXPECT_GE(groups, 6u);  // t = 0, 0.05, ..., 0.25 and the end
  const std::string last = "/snapshot_000005/";
  const auto pos = read_doubles(file, last + "position");
  const auto q = read_doubles(file, last + "orientation");
  const auto ax = read_doubles(file, last + "axis_x");
  const auto id = read_doubles(file, last + "id");
  ASSERT_EQ(pos.size(), 36u);
  ASSERT_EQ(q.size(), 48u);
  for (size_t i = 0; i < 12; ++i) {
    EXPECT_EQ(id[i], static_cast<double>(i));
    const Eigen::Quaterniond qi(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);
    EXPECT_NEAR(qi.norm(), 1.0, 1e-12);
    const Eigen::Vector3d x_axis = qi.toRotationMatrix().col(0);
    EXPECT_NEAR((x_axis - Eigen::Vector3d(ax[3 * i], ax[3 * i + 1], ax[3 * i + 2])).norm(), 0,
                1e-12);
    for (int d = 0; d < 2; ++d) {  // periodic x, y: wrapped into the box
      EXPECT_GE(pos[3 * i + d], 0.0);
      EXPECT_LT(pos[3 * i + d], 0.04);
    }
    // Above the floor by at least half an edge minus the (soft) contact overlap.
    EXPECT_GT(pos[3 * i + 2], 0.0045);
  }
  H5Fclose(file);
}

std::vector<long long> read_longs(hid_t file, const std::string& path) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  EXPECT_GE(set, 0) << path;
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  const auto n = static_cast<size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<long long> v(n);
  H5Dread(set, H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(space);
  H5Dclose(set);
  return v;
}

// The cubes' surfaces: 8 corners per body at x + R (+-a/2, +-a/2, +-a/2) with the rigid-body
// velocity v + w x (R r) there, 12 outward triangles per body indexing its own corners.
TEST(DemOutput, SurfacesAreEachCubePlacedAtItsPose) {
  const double half = 0.005;  // pour_small.yaml: edge 0.01
  const std::string h5 = output_dir() + "/pour_small_bodies.h5";
  const hid_t file = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0) << h5;
  const std::string last = "/snapshot_000005/";
  const auto pos = read_doubles(file, last + "position");
  const auto q = read_doubles(file, last + "orientation");
  const auto v = read_doubles(file, last + "velocity");
  const auto w = read_doubles(file, last + "angular_velocity");
  const auto points = read_doubles(file, last + "surface_points");
  const auto velocity = read_doubles(file, last + "surface_velocity");
  const auto owner = read_longs(file, last + "surface_id");
  const auto triangles = read_longs(file, last + "surface_triangles");
  H5Fclose(file);
  ASSERT_EQ(points.size(), 12u * 8 * 3);
  ASSERT_EQ(velocity.size(), points.size());
  ASSERT_EQ(owner.size(), 12u * 8);
  ASSERT_EQ(triangles.size(), 12u * 12 * 3);
  for (size_t p = 0; p < owner.size(); ++p) {
    const auto b = static_cast<size_t>(owner[p]);
    ASSERT_EQ(b, p / 8);
    const Eigen::Matrix3d r =
        Eigen::Quaterniond(q[4 * b], q[4 * b + 1], q[4 * b + 2], q[4 * b + 3]).toRotationMatrix();
    const Eigen::Vector3d arm =
        Eigen::Vector3d(points[3 * p], points[3 * p + 1], points[3 * p + 2]) -
        Eigen::Vector3d(pos[3 * b], pos[3 * b + 1], pos[3 * b + 2]);
    const Eigen::Vector3d local = r.transpose() * arm;
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(std::abs(local[d]), half, 1e-12) << "vertex " << p;
    const Eigen::Vector3d expected =
        Eigen::Vector3d(v[3 * b], v[3 * b + 1], v[3 * b + 2]) +
        Eigen::Vector3d(w[3 * b], w[3 * b + 1], w[3 * b + 2]).cross(arm);
    EXPECT_NEAR(
        (expected - Eigen::Vector3d(velocity[3 * p], velocity[3 * p + 1], velocity[3 * p + 2]))
            .norm(),
        0, 1e-12);
  }
  // Each triangle indexes three corners of one body; the 12 of a body enclose its volume.
  std::vector<double> volume(12, 0.0);
  for (size_t t = 0; t < triangles.size() / 3; ++t) {
    Eigen::Vector3d c[3];
    for (int k = 0; k < 3; ++k) {
      const auto i = static_cast<size_t>(triangles[3 * t + k]);
      ASSERT_LT(i, owner.size());
      EXPECT_EQ(static_cast<size_t>(owner[i]), t / 12);
      c[k] = Eigen::Vector3d(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    }
    volume[t / 12] += c[0].dot(c[1].cross(c[2])) / 6;
  }
  for (double vol : volume) EXPECT_NEAR(vol, 8 * half * half * half, 1e-15);
  std::ifstream xdmf(output_dir() + "/pour_small_surfaces.xdmf");
  ASSERT_TRUE(xdmf);
  std::stringstream text;
  text << xdmf.rdbuf();
  EXPECT_NE(text.str().find("TopologyType=\"Triangle\" NumberOfElements=\"144\""),
            std::string::npos);
  EXPECT_NE(text.str().find("pour_small_bodies.h5:/snapshot_000005/surface_points"),
            std::string::npos);
}

TEST(DemOutput, EnergySeriesShowsThePourComingToRest) {
  std::ifstream in(output_dir() + "/pour_small_energy.csv");
  ASSERT_TRUE(in);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time,kinetic_translational,kinetic_rotational,potential,contacts");
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::vector<double> r;
    for (std::string f; std::getline(s, f, ',');) r.push_back(std::stod(f));
    ASSERT_EQ(r.size(), 5u);
    rows.push_back(r);
  }
  ASSERT_GE(rows.size(), 25u);
  double peak = 0;
  for (const auto& r : rows) peak = std::max(peak, r[1] + r[2]);
  const auto& end = rows.back();
  EXPECT_LT(end[1] + end[2], 0.2 * peak);
  EXPECT_LT(end[3], rows.front()[3]);  // potential energy went down
  EXPECT_GT(end[4], 0);                // bodies touch each other
}

}  // namespace
