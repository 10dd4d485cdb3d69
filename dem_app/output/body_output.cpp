#include "dem_app/output/body_output.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "coupler_lib/output/atomic_file.hpp"
#include "coupler_lib/output/gather.hpp"
#include "coupler_lib/output/hdf5_handle.hpp"
#include "coupler_lib/output/xdmf.hpp"
#include "dem_app/output/output_chunks.hpp"

namespace lbdem {

std::vector<BodyState> gather_states(const std::vector<BodyState>& mine, MPI_Comm comm) {
  std::vector<BodyState> all = gather_to_root(std::span<const BodyState>(mine), comm);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return all;
}

namespace {

H5Handle create_dataset(hid_t group, const char* name, hid_t type, hsize_t rows, hsize_t cols) {
  const hsize_t dims[2] = {rows, cols};
  const H5Handle space(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr), H5Sclose,
                       std::string("dataspace of ") + name);
  return H5Handle(H5Dcreate2(group, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                  H5Dclose, std::string("create dataset ") + name);
}

// Rows [first, first + rows) of a dataset of `cols` columns.
void write_rows(hid_t set, hid_t type, const void* data, hsize_t first, hsize_t rows,
                hsize_t cols) {
  if (rows == 0) return;
  const hsize_t start[2] = {first, 0}, count[2] = {rows, cols};
  const H5Handle file_space(H5Dget_space(set), H5Sclose, "dataspace of a body dataset");
  h5_check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr),
           "select rows of a body dataset");
  const H5Handle memory(H5Screate_simple(cols == 1 ? 1 : 2, count, nullptr), H5Sclose,
                        "memory space of a body chunk");
  h5_check(H5Dwrite(set, type, memory, file_space, H5P_DEFAULT, data), "write body rows");
}

// The datasets of one snapshot, in the order they are created and written.
struct SnapshotColumn {
  const char* name;
  hid_t type;
  hsize_t cols;
};
const SnapshotColumn kColumns[] = {
    {"position", H5T_NATIVE_DOUBLE, 3}, {"orientation", H5T_NATIVE_DOUBLE, 4},
    {"velocity", H5T_NATIVE_DOUBLE, 3}, {"angular_velocity", H5T_NATIVE_DOUBLE, 3},
    {"axis_x", H5T_NATIVE_DOUBLE, 3},   {"axis_y", H5T_NATIVE_DOUBLE, 3},
    {"axis_z", H5T_NATIVE_DOUBLE, 3},   {"rotation", H5T_NATIVE_DOUBLE, 9},
    {"id", H5T_NATIVE_LLONG, 1},        {"shape", H5T_NATIVE_INT, 1}};

// The surface datasets of one snapshot (the vertices of every body in id order, then the
// triangles indexing them).
const SnapshotColumn kSurfaceColumns[] = {{"surface_points", H5T_NATIVE_DOUBLE, 3},
                                          {"surface_velocity", H5T_NATIVE_DOUBLE, 3},
                                          {"surface_id", H5T_NATIVE_LLONG, 1},
                                          {"surface_triangles", H5T_NATIVE_LLONG, 3}};

std::string group_name(int index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "snapshot_%06d", index);
  return buf;
}

}  // namespace

BodySnapshotWriter::BodySnapshotWriter(const std::string& directory, const std::string& name,
                                       MPI_Comm comm, std::vector<TriangleMesh> surfaces)
    : comm_(comm), surfaces_(std::move(surfaces)) {
  MPI_Comm_rank(comm_, &rank_);
  h5_name_ = name + "_bodies.h5";
  h5_path_ = (std::filesystem::path(directory) / h5_name_).string();
  xdmf_path_ = (std::filesystem::path(directory) / (name + "_bodies.xdmf")).string();
  if (!surfaces_.empty())
    surfaces_path_ = (std::filesystem::path(directory) / (name + "_surfaces.xdmf")).string();
  if (rank_ == 0) {
    std::filesystem::create_directories(directory);
    file_ = H5Handle(H5Fcreate(h5_path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                     "create " + h5_path_);
  }
}

void BodySnapshotWriter::write(const std::vector<BodyState>& owned, double time) {
  // Gathered and written in pieces of kOutputChunk ids (dem_app/output/output_chunks.hpp).
  const std::vector<BodyState> mine = sorted_by_id(std::span<const BodyState>(owned));
  const bool with_surfaces = !surfaces_.empty();
  auto surface = [&](const BodyState& b) -> const TriangleMesh& {
    if (b.shape < 0 || static_cast<size_t>(b.shape) >= surfaces_.size())
      throw std::logic_error("body snapshot: body " + std::to_string(b.id) +
                             " has no shape surface");
    return surfaces_[static_cast<size_t>(b.shape)];
  };
  // Bodies, surface vertices and surface triangles over all ranks.
  long long totals[3] = {static_cast<long long>(mine.size()), 0, 0};
  if (with_surfaces)
    for (const auto& b : mine) {
      totals[1] += static_cast<long long>(surface(b).vertices.size());
      totals[2] += static_cast<long long>(surface(b).triangles.size());
    }
  MPI_Allreduce(MPI_IN_PLACE, totals, 3, MPI_LONG_LONG, MPI_SUM, comm_);
  const auto n = static_cast<hsize_t>(totals[0]);
  const auto n_points = static_cast<hsize_t>(totals[1]);
  const auto n_triangles = static_cast<hsize_t>(totals[2]);
  const std::string g = group_name(count_);
  H5Handle group;
  std::vector<H5Handle> sets, surface_sets;
  if (rank_ == 0) {
    group = H5Handle(H5Gcreate2(file_, g.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                     "create group " + g);
    for (const auto& c : kColumns) sets.push_back(create_dataset(group, c.name, c.type, n, c.cols));
    if (with_surfaces)
      for (const auto& c : kSurfaceColumns)
        surface_sets.push_back(create_dataset(
            group, c.name, c.type, &c == &kSurfaceColumns[3] ? n_triangles : n_points, c.cols));
  }
  const std::int64_t end = id_end(mine, comm_);
  hsize_t row = 0, point_row = 0, triangle_row = 0;
  for (std::int64_t lo = 0; lo < end; lo += kOutputChunk) {
    const auto chunk = gather_id_range(mine, lo, std::min(end, lo + kOutputChunk), comm_);
    if (rank_ != 0) continue;
    std::vector<double> pos, quat, vel, omega, ax, ay, az, rot;
    std::vector<long long> id;
    std::vector<int> shape;
    for (const auto& s : chunk) {
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
    const void* data[] = {pos.data(), quat.data(), vel.data(), omega.data(), ax.data(),
                          ay.data(),  az.data(),   rot.data(), id.data(),    shape.data()};
    for (size_t k = 0; k < sets.size(); ++k)
      write_rows(sets[k], kColumns[k].type, data[k], row, chunk.size(), kColumns[k].cols);
    row += chunk.size();
    if (!with_surfaces) continue;
    // Each vertex at x + R r with the rigid-body velocity v + w x (R r) there.
    std::vector<double> points, point_velocity;
    std::vector<long long> point_id, triangles;
    for (const auto& s : chunk) {
      const TriangleMesh& mesh = surface(s);
      const Eigen::Matrix3d r =
          Eigen::Quaterniond(s.q[0], s.q[1], s.q[2], s.q[3]).normalized().toRotationMatrix();
      const Eigen::Vector3d x(s.x[0], s.x[1], s.x[2]), v(s.v[0], s.v[1], s.v[2]),
          w(s.w[0], s.w[1], s.w[2]);
      const auto first = static_cast<long long>(point_row + point_id.size());
      for (const auto& t : mesh.triangles)
        for (int c = 0; c < 3; ++c) triangles.push_back(first + t[c]);
      for (const auto& local : mesh.vertices) {
        const Eigen::Vector3d arm = r * local, p = x + arm, u = v + w.cross(arm);
        for (int d = 0; d < 3; ++d) {
          points.push_back(p[d]);
          point_velocity.push_back(u[d]);
        }
        point_id.push_back(s.id);
      }
    }
    const hsize_t chunk_points = point_id.size(), chunk_triangles = triangles.size() / 3;
    write_rows(surface_sets[0], H5T_NATIVE_DOUBLE, points.data(), point_row, chunk_points, 3);
    write_rows(surface_sets[1], H5T_NATIVE_DOUBLE, point_velocity.data(), point_row, chunk_points,
               3);
    write_rows(surface_sets[2], H5T_NATIVE_LLONG, point_id.data(), point_row, chunk_points, 1);
    write_rows(surface_sets[3], H5T_NATIVE_LLONG, triangles.data(), triangle_row, chunk_triangles,
               3);
    point_row += chunk_points;
    triangle_row += chunk_triangles;
  }
  if (rank_ == 0) {
    if (row != n) throw std::logic_error("body snapshot: body ids are not unique");
    write_attribute(group, "time", time);
    h5_check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush " + h5_path_);
    times_.push_back(time);
    sizes_.push_back(static_cast<long>(n));
    surface_points_.push_back(static_cast<long>(n_points));
    surface_triangles_.push_back(static_cast<long>(n_triangles));
    write_xdmf();
    if (with_surfaces) write_surfaces_xdmf();
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

void BodySnapshotWriter::write_surfaces_xdmf() const {
  std::vector<XdmfGrid> grids;
  for (size_t k = 0; k < times_.size(); ++k) {
    const long points = surface_points_[k], triangles = surface_triangles_[k];
    const std::string g = h5_name_ + ":/" + group_name(static_cast<int>(k)) + "/";
    XdmfGrid grid{
        "surfaces_" + std::to_string(k),
        times_[k],
        XdmfTriangles{points, XdmfArray{{points, 3}, "Float", 8, g + "surface_points"}, triangles,
                      XdmfArray{{triangles, 3}, "Int", 8, g + "surface_triangles"}},
        {}};
    grid.attributes.push_back(
        {"body_velocity", "Vector", XdmfArray{{points, 3}, "Float", 8, g + "surface_velocity"}});
    grid.attributes.push_back({"id", "Scalar", XdmfArray{{points}, "Int", 8, g + "surface_id"}});
    grids.push_back(std::move(grid));
  }
  write_file_atomically(surfaces_path_, xdmf_series("surfaces", grids));
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
