#pragma once
// DEM-only output: body snapshots as HDF5 + XDMF (ParaView: Polyvertex points with per-body
// attributes: position, orientation quaternion (w, x, y, z), velocity, angular velocity, id,
// shape, the shape axes in space axis_x/axis_y/axis_z and the rotation matrix as a tensor,
// column-major as VTK reads it, for the Tensor Glyph filter), optionally the body surfaces
// (each shape's display surface placed at each body's pose, with the rigid-body velocity at its
// vertices as body_velocity: <name>_surfaces.xdmf over the same HDF5 file), and a CSV energy
// time series.
// Rank 0 writes; the other ranks send it their bodies.
#include <hdf5.h>
#include <mpi.h>

#include <fstream>
#include <string>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/geometry/triangle_mesh.hpp"
#include "coupler_lib/output/hdf5_handle.hpp"
#include "dem_app/engine/lammps_engine.hpp"

namespace lbdem {

// One snapshot's bodies gathered on rank 0, sorted by id.
std::vector<BodyState> gather_states(const std::vector<BodyState>& mine, MPI_Comm comm);

class BodySnapshotWriter {
 public:
  // Files: <directory>/<name>_bodies.h5 and <name>_bodies.xdmf (rank 0 only), and with
  // `surfaces` (one per shape of the catalogue, in the shape frame; empty: none)
  // <name>_surfaces.xdmf.
  BodySnapshotWriter(const std::string& directory, const std::string& name, MPI_Comm comm,
                     std::vector<TriangleMesh> surfaces = {});
  BodySnapshotWriter(const BodySnapshotWriter&) = delete;
  BodySnapshotWriter& operator=(const BodySnapshotWriter&) = delete;

  // Collective: appends one snapshot at `time`, the owned states gathered on rank 0 in pieces
  // of kOutputChunk ids (dem_app/output/output_chunks.hpp).
  void write(const std::vector<BodyState>& owned, double time);
  int snapshots() const { return count_; }
  const std::string& h5_path() const { return h5_path_; }
  const std::string& xdmf_path() const { return xdmf_path_; }
  // Empty without surfaces.
  const std::string& surfaces_path() const { return surfaces_path_; }

 private:
  void write_xdmf() const;
  void write_surfaces_xdmf() const;

  MPI_Comm comm_;
  int rank_ = 0;
  std::string h5_path_, xdmf_path_, h5_name_, surfaces_path_;
  std::vector<TriangleMesh> surfaces_;
  H5Handle file_;  // rank 0 only
  int count_ = 0;
  std::vector<double> times_;
  std::vector<long> sizes_;
  std::vector<long> surface_points_, surface_triangles_;
};

// CSV rows: time, kinetic energy (translational, rotational), potential energy, contacts.
class EnergySeries {
 public:
  EnergySeries(const std::string& path, MPI_Comm comm);
  void write(double time, const DemEnergies& e);  // rank 0 writes; call on all ranks
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int rank_ = 0;
  std::ofstream out_;
};

}  // namespace lbdem
