#include "dem_app/body_output.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "coupler_lib/output/atomic_file.hpp"
#include "coupler_lib/output/gather.hpp"
#include "coupler_lib/output/hdf5_handle.hpp"
#include "coupler_lib/output/xdmf.hpp"

namespace lbdem {

std::vector<BodyState> gather_states(const std::vector<BodyState>& mine, MPI_Comm comm) {
  std::vector<BodyState> all = gather_to_root(std::span<const BodyState>(mine), comm);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return all;
}

namespace {

void write_dataset(hid_t group, const char* name, hid_t type, const void* data, hsize_t rows,
                   hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  const H5Handle space(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr), H5Sclose,
                       std::string("dataspace of ") + name);
  const H5Handle set(H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     H5Dclose, std::string("create dataset ") + name);
  h5_check(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), std::string("write ") + name);
}

std::string group_name(int index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "snapshot_%06d", index);
  return buf;
}

}  // namespace

BodySnapshotWriter::BodySnapshotWriter(const std::string& directory, const std::string& name,
                                       MPI_Comm comm)
    : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  h5_name_ = name + "_bodies.h5";
  h5_path_ = (std::filesystem::path(directory) / h5_name_).string();
  xdmf_path_ = (std::filesystem::path(directory) / (name + "_bodies.xdmf")).string();
  if (rank_ == 0) {
    std::filesystem::create_directories(directory);
    file_ = H5Handle(H5Fcreate(h5_path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                     "create " + h5_path_);
  }
}

void BodySnapshotWriter::write(const std::vector<BodyState>& owned, double time) {
  const auto all = gather_states(owned, comm_);
  if (rank_ == 0) {
    const auto n = static_cast<hsize_t>(all.size());
    std::vector<double> pos, quat, vel, omega, ax, ay, az, rot;
    std::vector<long long> id;
    std::vector<int> shape;
    for (const auto& s : all) {
      const Eigen::Matrix3d r =
          Eigen::Quaterniond(s.q[0], s.q[1], s.q[2], s.q[3]).normalized().toRotationMatrix();
      for (int d = 0; d < 3; ++d) {
        pos.push_back(s.x[d]);
        vel.push_back(s.v[d]);
        omega.push_back(s.w[d]);
        ax.push_back(r(d, 0));  // shape x axis in space
        ay.push_back(r(d, 1));
        az.push_back(r(d, 2));
      }
      for (int d = 0; d < 4; ++d) quat.push_back(s.q[d]);
      // Column-major, as VTK reads a 3x3 tensor: components 0-2 are the shape's x axis.
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) rot.push_back(r(i, j));
      id.push_back(s.id);
      shape.push_back(s.shape);
    }
    const std::string g = group_name(count_);
    const H5Handle group(H5Gcreate2(file_, g.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         H5Gclose, "create group " + g);
    write_dataset(group, "position", H5T_NATIVE_DOUBLE, pos.data(), n, 3);
    write_dataset(group, "orientation", H5T_NATIVE_DOUBLE, quat.data(), n, 4);
    write_dataset(group, "velocity", H5T_NATIVE_DOUBLE, vel.data(), n, 3);
    write_dataset(group, "angular_velocity", H5T_NATIVE_DOUBLE, omega.data(), n, 3);
    write_dataset(group, "axis_x", H5T_NATIVE_DOUBLE, ax.data(), n, 3);
    write_dataset(group, "axis_y", H5T_NATIVE_DOUBLE, ay.data(), n, 3);
    write_dataset(group, "axis_z", H5T_NATIVE_DOUBLE, az.data(), n, 3);
    write_dataset(group, "rotation", H5T_NATIVE_DOUBLE, rot.data(), n, 9);
    write_dataset(group, "id", H5T_NATIVE_LLONG, id.data(), n, 1);
    write_dataset(group, "shape", H5T_NATIVE_INT, shape.data(), n, 1);
    write_attribute(group, "time", time);
    h5_check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush " + h5_path_);
    times_.push_back(time);
    sizes_.push_back(static_cast<long>(n));
    write_xdmf();
  }
  ++count_;
}

void BodySnapshotWriter::write_xdmf() const {
  // Rewritten whole after each snapshot, so a partial run is always readable.
  std::vector<XdmfGrid> grids;
  for (size_t k = 0; k < times_.size(); ++k) {
    const long n = sizes_[k];
    const std::string g = h5_name_ + ":/" + group_name(static_cast<int>(k)) + "/";
    auto array = [&](const char* set, long cols, const char* type, int bytes) {
      std::vector<long> dims{n};
      if (cols > 1) dims.push_back(cols);
      return XdmfArray{dims, type, bytes, g + set};
    };
    XdmfGrid grid{"bodies_" + std::to_string(k),
                  times_[k],
                  XdmfPoints{n, array("position", 3, "Float", 8)},
                  {}};
    auto attribute = [&](const char* name, const char* kind, long cols, const char* type,
                         int bytes) {
      grid.attributes.push_back({name, kind, array(name, cols, type, bytes)});
    };
    attribute("velocity", "Vector", 3, "Float", 8);
    attribute("angular_velocity", "Vector", 3, "Float", 8);
    attribute("axis_x", "Vector", 3, "Float", 8);
    attribute("axis_y", "Vector", 3, "Float", 8);
    attribute("axis_z", "Vector", 3, "Float", 8);
    attribute("rotation", "Tensor", 9, "Float", 8);
    attribute("orientation", "Matrix", 4, "Float", 8);
    attribute("id", "Scalar", 1, "Int", 8);
    attribute("shape", "Scalar", 1, "Int", 4);
    grids.push_back(std::move(grid));
  }
  write_file_atomically(xdmf_path_, xdmf_series("bodies", grids));
}

EnergySeries::EnergySeries(const std::string& path, MPI_Comm comm) : path_(path) {
  MPI_Comm_rank(comm, &rank_);
  if (rank_ == 0) {
    const auto dir = std::filesystem::path(path).parent_path();
    if (!dir.empty()) std::filesystem::create_directories(dir);
    out_.open(path);
    if (!out_) throw std::runtime_error("cannot create " + path);
    out_ << "time,kinetic_translational,kinetic_rotational,potential,contacts\n";
    out_.precision(12);
  }
}

void EnergySeries::write(double time, const DemEnergies& e) {
  if (rank_ != 0) return;
  out_ << time << "," << e.kinetic_translational << "," << e.kinetic_rotational << ","
       << e.potential << "," << e.contacts << "\n";
  out_.flush();
}

}  // namespace lbdem
