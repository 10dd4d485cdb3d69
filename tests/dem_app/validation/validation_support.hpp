#pragma once
// Helpers for the DEM validation cases: scenes from configs/dem/validation, body states from
// every rank, and the one-line report (error and run time) each case prints.
#include <mpi.h>

#include <Eigen/Geometry>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/engine/lammps_engine.hpp"
#include "dem_app/output/body_output.hpp"
#include "dem_app/setup/dem_setup.hpp"

namespace lbdem::test {

inline std::string validation_scene(const std::string& name) {
  return std::string(LBDEM_SOURCE_DIR) + "/configs/dem/validation/" + name;
}

// The DEM setup of a scene file exactly as dem_app builds it.
inline DemSetup load_setup(const std::string& file, bool external_loads = false) {
  const Scene scene = load_scene(file);
  DemSetup s = make_dem_setup(scene, build_scene_shapes(scene), external_loads);
  s.lammps_log =
      (std::filesystem::temp_directory_path() / "lbdem_dem_validation_lammps.log").string();
  return s;
}

// Every body's state on every rank, sorted by id.
inline std::vector<BodyState> all_states(const LammpsEngine& e) {
  auto all = gather_states(e.owned_states(0), e.comm());
  int n = static_cast<int>(all.size());
  MPI_Bcast(&n, 1, MPI_INT, 0, e.comm());
  all.resize(static_cast<size_t>(n));
  MPI_Bcast(all.data(), n * static_cast<int>(sizeof(BodyState)), MPI_BYTE, 0, e.comm());
  return all;
}

inline int world_rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

inline int world_size() {
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

// Inertia tensor of a homogeneous cuboid of mass m and edges e about its centre, in the frame of
// its edges (the textbook m / 12 (b^2 + c^2), ...): the independent reference of the mass
// properties the engine derives from the shape.
inline Eigen::Matrix3d cuboid_inertia(double m, const Eigen::Vector3d& e) {
  const Eigen::Vector3d s = e.cwiseProduct(e);
  return Eigen::Vector3d(s[1] + s[2], s[0] + s[2], s[0] + s[1]).asDiagonal() * (m / 12.0);
}

class WallTimer {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// "[validation] <case>: <reference> error <e>, tolerance <tol> (run time <t> s, <n> ranks)" on
// rank 0; tools/validation_table.py collects these lines into docs/validation-table.md.
inline void report(const std::string& name, const std::string& what, double error, double tolerance,
                   double seconds) {
  if (world_rank() == 0)
    std::printf("[validation] %s: %s error %.3e, tolerance %.1e (run time %.2f s, %d rank%s)\n",
                name.c_str(), what.c_str(), error, tolerance, seconds, world_size(),
                world_size() > 1 ? "s" : "");
}

}  // namespace lbdem::test
