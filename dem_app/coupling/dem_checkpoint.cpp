#include "dem_app/coupling/dem_checkpoint.hpp"

#include <hdf5.h>

#include <filesystem>
#include <stdexcept>

#include "coupler_lib/coupling/journal.hpp"
#include "coupler_lib/output/hdf5_handle.hpp"

namespace lbdem {

namespace {

// Whether any rank of `side` failed; a failing rank throws its own message, the others a
// short one (so every rank leaves together).
void throw_if_any(const std::string& error, const std::string& what, MPI_Comm side) {
  int failed = error.empty() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, side);
  if (failed) throw std::runtime_error(error.empty() ? what + " failed on another rank" : error);
}

}  // namespace

void write_dem_checkpoint(const std::string& prefix, const std::string& journal,
                          const CheckpointHeader& header, long long trace_bytes, MPI_Comm side) {
  int rank = 0;
  MPI_Comm_rank(side, &rank);
  const std::string final_path = dem_half(prefix);
  // Each rank its own part first; the file that names the checkpoint complete comes last.
  std::string error;
  const std::string part = journal_part(final_path, rank), part_tmp = part + ".tmp";
  try {
    std::filesystem::copy_file(journal, part_tmp,
                               std::filesystem::copy_options::overwrite_existing);
    std::filesystem::rename(part_tmp, part);
  } catch (const std::exception& e) {
    error = "writing the DEM checkpoint part " + part + ": " + e.what();
  }
  throw_if_any(error, "writing the DEM checkpoint parts", side);
  if (rank == 0) {
    const std::string tmp = final_path + ".tmp";
    try {
      {
        const H5Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                            H5Fclose, "creating " + tmp);
        write_checkpoint_header(file, header);
        write_attribute(file, "trace_bytes", trace_bytes);
      }
      std::filesystem::rename(tmp, final_path);
    } catch (const std::exception& e) {
      error = std::string("writing the DEM checkpoint ") + final_path + ": " + e.what();
    }
  }
  throw_if_any(error, "writing the DEM checkpoint", side);
}

DemRestart read_dem_checkpoint(const std::string& prefix, const CheckpointHeader& expected,
                               int rank) {
  DemRestart r;
  r.path = dem_half(prefix);
  r.part = journal_part(r.path, rank);
  r.header = read_checkpoint_header(r.path);
  check_checkpoint_header(r.path, r.header, expected, true);
  if (!std::filesystem::is_regular_file(r.part))
    throw std::runtime_error("cannot restart from " + r.path + ": its journal part " + r.part +
                             " of DEM rank " + std::to_string(rank) +
                             " is missing (every DEM rank reads its own part)");
  const H5Handle file(H5Fopen(r.path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
                      "opening " + r.path);
  r.trace_bytes = read_llong_attribute(file, "trace_bytes");
  return r;
}

}  // namespace lbdem
