#include "dem_app/coupling/dem_checkpoint.hpp"

#include <hdf5.h>

#include <filesystem>
#include <stdexcept>

#include "coupler_lib/output/hdf5_handle.hpp"

namespace lbdem {

void write_dem_checkpoint(const std::string& prefix, const std::string& journal,
                          const CheckpointHeader& header, long long trace_bytes, MPI_Comm side) {
  int rank = 0;
  MPI_Comm_rank(side, &rank);
  std::string error;
  if (rank == 0) {
    const std::string final_path = dem_half(prefix), tmp = final_path + ".tmp";
    try {
      std::filesystem::copy_file(journal, tmp, std::filesystem::copy_options::overwrite_existing);
      {
        const H5Handle file(H5Fopen(tmp.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose,
                            "opening " + tmp);
        write_checkpoint_header(file, header);
        write_attribute(file, "trace_bytes", trace_bytes);
      }
      std::filesystem::rename(tmp, final_path);
    } catch (const std::exception& e) {
      error = std::string("writing the DEM checkpoint ") + final_path + ": " + e.what();
    }
  }
  int failed = error.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, side);
  if (failed) throw std::runtime_error(rank == 0 ? error : "writing the DEM checkpoint failed");
}

DemRestart read_dem_checkpoint(const std::string& prefix, const CheckpointHeader& expected) {
  DemRestart r;
  r.path = dem_half(prefix);
  r.header = read_checkpoint_header(r.path);
  check_checkpoint_header(r.path, r.header, expected, true);
  const H5Handle file(H5Fopen(r.path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                      "opening " + r.path);
  r.trace_bytes = read_llong_attribute(file, "trace_bytes");
  return r;
}

}  // namespace lbdem
