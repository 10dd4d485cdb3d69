#pragma once
// Shared by the output and stability unit tests: MPI for the HDF5 MPI-IO driver (one process,
// MPI_COMM_SELF), a scratch directory, a synthetic lattice state and an HDF5 reader.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <mpi.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "fluid_app/output/macro_fields.hpp"

namespace lbdem::test {

// Initializes MPI once for the whole test program unless something else already did.
class MpiEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      MPI_Init(nullptr, nullptr);
      owner_ = true;
    }
  }
  void TearDown() override {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (owner_ && !finalized) MPI_Finalize();
  }

 private:
  bool owner_ = false;
};

inline ::testing::Environment* const kMpiEnvironment =
    ::testing::AddGlobalTestEnvironment(new MpiEnvironment);

// A fresh, empty directory under the system temp dir, removed on destruction.
struct ScratchDir {
  std::filesystem::path path;
  explicit ScratchDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             (name + "_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
              std::to_string(reinterpret_cast<std::uintptr_t>(this)))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() { std::filesystem::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

// Distinct values at every global node so a misplaced sample cannot go unnoticed.
inline double test_rho(int i, int j, int k) {
  return 1.0 + 1e-3 * i + 1e-5 * j + 1e-7 * k;
}
inline double test_u(int i, int j, int k, int d) {
  return 1e-3 * (d + 1) + 1e-4 * i - 2e-6 * j + 3e-8 * k;
}

inline MacroFields test_fields(const FieldBlock& box) {
  MacroFields f;
  f.resize(box);
  for (int k = 0; k < box.n[2]; ++k)
    for (int j = 0; j < box.n[1]; ++j)
      for (int i = 0; i < box.n[0]; ++i) {
        const int gi = i + box.lo[0], gj = j + box.lo[1], gk = k + box.lo[2];
        const std::size_t c = box.index(i, j, k);
        f.rho[c] = test_rho(gi, gj, gk);
        for (int d = 0; d < 3; ++d) f.u[3 * c + d] = test_u(gi, gj, gk, d);
      }
  return f;
}

// A whole dataset as doubles (serial HDF5 read), with its dimensions.
struct Dataset {
  std::vector<hsize_t> dims;
  std::vector<double> values;
};

inline Dataset read_dataset(const std::string& file, const std::string& name) {
  Dataset d;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return d;
  const hid_t ds = H5Lexists(f, name.c_str(), H5P_DEFAULT) > 0
                       ? H5Dopen2(f, name.c_str(), H5P_DEFAULT)
                       : H5I_INVALID_HID;
  if (ds >= 0) {
    const hid_t space = H5Dget_space(ds);
    d.dims.resize(H5Sget_simple_extent_ndims(space));
    H5Sget_simple_extent_dims(space, d.dims.data(), nullptr);
    d.values.resize(H5Sget_simple_extent_npoints(space));
    H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data());
    H5Sclose(space);
    H5Dclose(ds);
  }
  H5Fclose(f);
  return d;
}

inline double read_double_attribute(const std::string& file, const std::string& object,
                                    const std::string& name) {
  double v = -1;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return v;
  const hid_t a = H5Aopen_by_name(f, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
  }
  H5Fclose(f);
  return v;
}

}  // namespace lbdem::test
