#pragma once
// Owning wrappers for HDF5 identifiers and the parallel (MPI-IO) file set-up shared by the
// field writer and the last-good-state writer.
#include <hdf5.h>
#include <mpi.h>

#include <string>
#include <utility>

namespace lbdem {

// One HDF5 identifier and the function that releases it (H5Fclose, H5Dclose, ...).
class H5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  // Throws std::runtime_error naming `what` when `id` is invalid (the call failed).
  H5Handle(hid_t id, Closer close, const std::string& what = "an HDF5 call");
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  H5Handle(H5Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), close_(o.close_) {}
  H5Handle& operator=(H5Handle&& o) noexcept;
  ~H5Handle() { reset(); }

  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }
  void reset();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer close_ = nullptr;
};

// Throws std::runtime_error naming `what` when an HDF5 call returned a negative status.
void h5_check(herr_t status, const std::string& what);

// While alive, HDF5 prints no error stack of its own on failed calls: the caller words the
// message (a file that is missing or not HDF5 is reported once, by that message).
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Creates (truncating) `path` for collective writing by every rank of `comm` (MPI-IO).
H5Handle create_parallel_file(const std::string& path, MPI_Comm comm);

// Opens an existing `path` read-only for every rank of `comm` (MPI-IO). Throws
// std::runtime_error naming the file when it is missing or not HDF5 (truncated, overwritten).
H5Handle open_parallel_file(const std::string& path, MPI_Comm comm);

// A property list for collective dataset transfers.
H5Handle collective_transfer();

// Scalar attributes on a file, group or dataset.
void write_attribute(hid_t object, const std::string& name, double value);
void write_attribute(hid_t object, const std::string& name, long long value);
void write_attribute(hid_t object, const std::string& name, const std::string& value);
// Their readers; throw std::runtime_error naming the attribute when it is missing.
double read_double_attribute(hid_t object, const std::string& name);
long long read_llong_attribute(hid_t object, const std::string& name);
std::string read_string_attribute(hid_t object, const std::string& name);

}  // namespace lbdem
