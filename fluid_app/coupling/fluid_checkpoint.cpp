#include "fluid_app/coupling/fluid_checkpoint.hpp"

#include <hdf5.h>
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "coupler_lib/output/gather.hpp"
#include "coupler_lib/output/hdf5_handle.hpp"
#include "fluid_app/lattice/d3q19.hpp"

namespace lbdem {

namespace {

// force, controller integral, impulse, mean velocity (3 each), mass
constexpr int kMemoryValues = 13;
constexpr int kCoveredValues = 11;  // rank, id, Q (3), L (3), centre (3)

template <class T>
hid_t h5_type() {
  return sizeof(T) == 8 ? H5T_NATIVE_DOUBLE : H5T_NATIVE_FLOAT;
}

std::uint64_t mix(std::uint64_t z) {  // splitmix64 finalizer
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Order-free checksum of the rank's block: a sum over values of a hash of (global position,
// bits), so every decomposition of the same lattice gives the same total.
template <class T>
std::uint64_t block_checksum(const std::vector<T>& v, const LocalBox& b) {
  std::uint64_t sum = 0;
  std::size_t k = 0;
  for (int i = 0; i < d3q19::Q; ++i)
    for (int z = 0; z < b.n[2]; ++z)
      for (int y = 0; y < b.n[1]; ++y)
        for (int x = 0; x < b.n[0]; ++x) {
          const std::uint64_t g =
              ((std::uint64_t(i) * std::uint64_t(b.global[2]) + std::uint64_t(b.offset[2] + z)) *
                   std::uint64_t(b.global[1]) +
               std::uint64_t(b.offset[1] + y)) *
                  std::uint64_t(b.global[0]) +
              std::uint64_t(b.offset[0] + x);
          std::uint64_t bits = 0;
          std::memcpy(&bits, &v[k++], sizeof(T));
          sum += mix(bits ^ mix(g + 0x9e3779b97f4a7c15ULL));
        }
  return sum;
}

std::string hex(std::uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

// The block of this rank in [19][nz][ny][nx].
H5Handle block_space(hid_t dataset, const LocalBox& b) {
  H5Handle space(H5Dget_space(dataset), H5Sclose, "population space");
  const hsize_t start[4] = {0, hsize_t(b.offset[2]), hsize_t(b.offset[1]), hsize_t(b.offset[0])};
  const hsize_t count[4] = {hsize_t(d3q19::Q), hsize_t(b.n[2]), hsize_t(b.n[1]), hsize_t(b.n[0])};
  h5_check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr),
           "selecting the block");
  return space;
}

// A small 2-D double table written by rank 0 alone (collective call, empty selection
// elsewhere).
void write_table(hid_t file, const char* name, const std::vector<double>& rows, int cols,
                 int rank) {
  const hsize_t dims[2] = {hsize_t(rows.size() / std::size_t(cols)), hsize_t(cols)};
  H5Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose, "table space");
  H5Handle set(
      H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, std::string("creating ") + name);
  H5Handle mem(H5Screate_simple(2, dims, nullptr), H5Sclose, "table memory");
  H5Handle file_space(H5Dget_space(set), H5Sclose, "table file space");
  if (rank != 0 || dims[0] == 0) {
    H5Sselect_none(mem);
    H5Sselect_none(file_space);
  }
  const H5Handle xfer = collective_transfer();
  h5_check(H5Dwrite(set, H5T_NATIVE_DOUBLE, mem, file_space, xfer, rows.data()),
           std::string("writing ") + name);
}

std::vector<double> read_table(hid_t file, const char* name, int cols) {
  H5Handle set(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose, std::string("opening ") + name);
  H5Handle space(H5Dget_space(set), H5Sclose, "table space");
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  if (dims[1] != hsize_t(cols))
    throw std::runtime_error(std::string(name) + " has " + std::to_string(dims[1]) +
                             " columns where this fluid_app expects " + std::to_string(cols) +
                             ": written by another version");
  std::vector<double> rows(dims[0] * dims[1]);
  if (!rows.empty())
    h5_check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data()),
             std::string("reading ") + name);
  return rows;
}

constexpr const char* kAxes[3] = {"x", "y", "z"};

// One column per slice; an empty table is not written.
void write_slices(hid_t file, const std::string& name, const SliceWeights& w, int rank) {
  for (int a = 0; a < 3; ++a)
    if (!w[a].empty()) write_table(file, (name + "_" + kAxes[a]).c_str(), w[a], 1, rank);
}

SliceWeights read_slices(hid_t file, const std::string& name) {
  SliceWeights w;
  for (int a = 0; a < 3; ++a) {
    const std::string set = name + "_" + kAxes[a];
    if (H5Lexists(file, set.c_str(), H5P_DEFAULT) > 0) w[a] = read_table(file, set.c_str(), 1);
  }
  return w;
}

}  // namespace

template <class T>
void write_fluid_checkpoint(const std::string& prefix, const CheckpointHeader& header,
                            const FluidSolver<T>& solver,
                            const std::array<double, 3>& control_integral,
                            std::span<const CoveredRecord> mine, const SeriesLengths& lengths,
                            const CheckpointWork& work) {
  const MPI_Comm comm = solver.comm();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::string final_path = fluid_half(prefix), tmp = final_path + ".tmp";
  const LocalBox& b = solver.box();
  std::vector<T> block;
  solver.interior_populations(block);
  std::uint64_t sum = block_checksum(block, b);
  MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_UINT64_T, MPI_SUM, comm);
  // Attributes of a parallel file take the same value on every rank: rank 0's lengths.
  long long length[2] = {lengths.series, lengths.momentum};
  MPI_Bcast(length, 2, MPI_LONG_LONG, 0, comm);
  {
    const H5Handle file = create_parallel_file(tmp, comm);
    write_checkpoint_header(file, header);
    write_attribute(file, "population_checksum", hex(sum));
    write_attribute(file, "series_bytes", length[0]);
    write_attribute(file, "momentum_bytes", length[1]);
    write_attribute(file, "precision", std::string(sizeof(T) == 8 ? "double" : "float"));
    write_attribute(file, "measured_imbalance", work.imbalance);
    write_slices(file, "measured_work", work.measured, rank);
    write_slices(file, "layout_weights", work.layout, rank);
    const hsize_t dims[4] = {hsize_t(d3q19::Q), hsize_t(b.global[2]), hsize_t(b.global[1]),
                             hsize_t(b.global[0])};
    const H5Handle space(H5Screate_simple(4, dims, nullptr), H5Sclose, "population space");
    const H5Handle set(
        H5Dcreate2(file, "populations", h5_type<T>(), space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        H5Dclose, "creating populations in " + tmp);
    const H5Handle file_space = block_space(set, b);
    const hsize_t n = block.size();
    const H5Handle mem(H5Screate_simple(1, &n, nullptr), H5Sclose, "block memory");
    const H5Handle xfer = collective_transfer();
    h5_check(H5Dwrite(set, h5_type<T>(), mem, file_space, xfer, block.data()),
             "writing the populations to " + tmp);

    const SolverMemory m = solver.memory();
    std::vector<double> memory;
    for (const auto* a : {&m.force, &control_integral, &m.impulse, &m.mean.velocity})
      memory.insert(memory.end(), a->begin(), a->end());
    memory.push_back(m.mean.mass);
    write_table(file, "solver_memory", memory, kMemoryValues, rank);

    std::vector<double> covered;
    for (const CoveredRecord& r : gather_to_root(mine, comm)) {
      covered.push_back(double(r.rank));
      covered.push_back(double(r.id));
      covered.insert(covered.end(), r.covered.begin(), r.covered.end());
      covered.insert(covered.end(), r.covered_moment.begin(), r.covered_moment.end());
      covered.insert(covered.end(), r.centre.begin(), r.centre.end());
    }
    int rows = int(covered.size() / kCoveredValues);
    MPI_Bcast(&rows, 1, MPI_INT, 0, comm);
    if (rank != 0) covered.assign(std::size_t(rows) * kCoveredValues, 0.0);
    write_table(file, "covered", covered, kCoveredValues, rank);
  }
  MPI_Barrier(comm);
  if (rank == 0) std::filesystem::rename(tmp, final_path);
  MPI_Barrier(comm);
}

template <class T>
FluidRestart read_fluid_checkpoint(const std::string& prefix, const CheckpointHeader& expected,
                                   const FluidSolver<T>& solver, std::vector<T>& block) {
  const std::string path = fluid_half(prefix);
  FluidRestart r;
  const MPI_Comm comm = solver.comm();
  const LocalBox& b = solver.box();
  block.assign(std::size_t(d3q19::Q) * std::size_t(b.interior_cells()), T(0));
  std::string recorded_sum;
  try {
    const H5Handle file = open_parallel_file(path, comm);
    r.header = read_checkpoint_header(file);
    check_checkpoint_header(path, r.header, expected, false);
    if (read_string_attribute(file, "precision") != (sizeof(T) == 8 ? "double" : "float"))
      throw std::runtime_error("written in another fluid.precision");
    recorded_sum = read_string_attribute(file, "population_checksum");
    r.lengths.series = read_llong_attribute(file, "series_bytes");
    r.lengths.momentum = read_llong_attribute(file, "momentum_bytes");
    const H5Handle set(H5Dopen2(file, "populations", H5P_DEFAULT), H5Dclose,
                       "opening the populations");
    const H5Handle fspace(H5Dget_space(set), H5Sclose, "population space");
    hsize_t dims[4] = {0, 0, 0, 0};
    if (H5Sget_simple_extent_ndims(fspace) != 4) throw std::runtime_error("populations not 4-D");
    H5Sget_simple_extent_dims(fspace, dims, nullptr);
    if (dims[0] != hsize_t(d3q19::Q) || dims[1] != hsize_t(b.global[2]) ||
        dims[2] != hsize_t(b.global[1]) || dims[3] != hsize_t(b.global[0]))
      throw std::runtime_error("the lattice in the file is not this scene's lattice");
    const H5Handle file_space = block_space(set, b);
    const hsize_t n = block.size();
    const H5Handle mem(H5Screate_simple(1, &n, nullptr), H5Sclose, "block memory");
    const H5Handle xfer = collective_transfer();
    h5_check(H5Dread(set, h5_type<T>(), mem, file_space, xfer, block.data()),
             "reading the populations");
    const std::vector<double> m = read_table(file, "solver_memory", kMemoryValues);
    if (m.size() != std::size_t(kMemoryValues)) throw std::runtime_error("solver_memory size");
    SolverMemory& mem_state = r.memory;
    mem_state.steps = r.header.step;
    for (int k = 0; k < 3; ++k) {
      mem_state.force[k] = m[k];
      r.control_integral[k] = m[3 + k];
      mem_state.impulse[k] = m[6 + k];
      mem_state.mean.velocity[k] = m[9 + k];
    }
    mem_state.mean.mass = m[12];
    const std::vector<double> c = read_table(file, "covered", kCoveredValues);
    for (std::size_t i = 0; i + kCoveredValues <= c.size(); i += kCoveredValues) {
      CoveredRecord rec;
      rec.rank = std::int64_t(c[i]);
      rec.id = std::int64_t(c[i + 1]);
      for (int k = 0; k < 3; ++k) {
        rec.covered[k] = c[i + 2 + k];
        rec.covered_moment[k] = c[i + 5 + k];
        rec.centre[k] = c[i + 8 + k];
      }
      r.covered.push_back(rec);
    }
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    if (what.rfind("cannot restart", 0) == 0) throw;
    throw std::runtime_error("cannot restart from " + path + ": not a usable fluid checkpoint (" +
                             what + "); give an older checkpoint of the folder");
  }
  std::uint64_t sum = block_checksum(block, b);
  MPI_Allreduce(MPI_IN_PLACE, &sum, 1, MPI_UINT64_T, MPI_SUM, comm);
  if (hex(sum) != recorded_sum)
    throw std::runtime_error("cannot restart from " + path +
                             ": the populations do not match their checksum (the file is "
                             "corrupted); give an older checkpoint of the folder");
  return r;
}

CheckpointWork read_checkpoint_work(const std::string& prefix, MPI_Comm comm) {
  const std::string path = fluid_half(prefix);
  CheckpointWork w;
  try {
    const H5Handle file = open_parallel_file(path, comm);
    w.fluid_ranks = read_checkpoint_header(file).fluid_ranks;
    w.imbalance = read_double_attribute(file, "measured_imbalance");
    w.measured = read_slices(file, "measured_work");
    w.layout = read_slices(file, "layout_weights");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("cannot restart from " + path + ": not a usable fluid checkpoint (" +
                             e.what() + "); give an older checkpoint of the folder");
  }
  return w;
}

template void write_fluid_checkpoint<double>(const std::string&, const CheckpointHeader&,
                                             const FluidSolver<double>&,
                                             const std::array<double, 3>&,
                                             std::span<const CoveredRecord>, const SeriesLengths&,
                                             const CheckpointWork&);
template void write_fluid_checkpoint<float>(const std::string&, const CheckpointHeader&,
                                            const FluidSolver<float>&, const std::array<double, 3>&,
                                            std::span<const CoveredRecord>, const SeriesLengths&,
                                            const CheckpointWork&);
template FluidRestart read_fluid_checkpoint<double>(const std::string&, const CheckpointHeader&,
                                                    const FluidSolver<double>&,
                                                    std::vector<double>&);
template FluidRestart read_fluid_checkpoint<float>(const std::string&, const CheckpointHeader&,
                                                   const FluidSolver<float>&, std::vector<float>&);

}  // namespace lbdem
