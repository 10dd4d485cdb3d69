#include "coupler_lib/output/hdf5_handle.hpp"

#include <stdexcept>

namespace lbdem {

H5Handle::H5Handle(hid_t id, Closer close, const std::string& what) : id_(id), close_(close) {
  if (id_ < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

H5Handle& H5Handle::operator=(H5Handle&& o) noexcept {
  if (this != &o) {
    reset();
    id_ = std::exchange(o.id_, H5I_INVALID_HID);
    close_ = o.close_;
  }
  return *this;
}

void H5Handle::reset() {
  if (id_ >= 0 && close_) close_(id_);
  id_ = H5I_INVALID_HID;
}

void h5_check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}

H5Handle create_parallel_file(const std::string& path, MPI_Comm comm) {
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access list");
  h5_check(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL), "H5Pset_fapl_mpio");
  return H5Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose,
                  "creating " + path);
}

H5Handle open_parallel_file(const std::string& path, MPI_Comm comm) {
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access list");
  h5_check(H5Pset_fapl_mpio(fapl, comm, MPI_INFO_NULL), "H5Pset_fapl_mpio");
  const hid_t id = [&] {
    const QuietHdf5 quiet;
    return H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl);
  }();
  return H5Handle(id, H5Fclose, "opening " + path + " (missing, truncated or not HDF5)");
}

H5Handle collective_transfer() {
  H5Handle dxpl(H5Pcreate(H5P_DATASET_XFER), H5Pclose, "transfer list");
  h5_check(H5Pset_dxpl_mpio(dxpl, H5FD_MPIO_COLLECTIVE), "H5Pset_dxpl_mpio");
  return dxpl;
}

namespace {
void write_attribute_raw(hid_t object, const std::string& name, hid_t type, const void* data) {
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  H5Handle attr(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
                "attribute " + name);
  h5_check(H5Awrite(attr, type, data), "writing attribute " + name);
}
void read_attribute_raw(hid_t object, const std::string& name, hid_t type, void* data) {
  if (H5Aexists(object, name.c_str()) <= 0)
    throw std::runtime_error("attribute '" + name + "' is missing");
  H5Handle attr(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  h5_check(H5Aread(attr, type, data), "reading attribute " + name);
}
}  // namespace

double read_double_attribute(hid_t object, const std::string& name) {
  double v = 0;
  read_attribute_raw(object, name, H5T_NATIVE_DOUBLE, &v);
  return v;
}

long long read_llong_attribute(hid_t object, const std::string& name) {
  long long v = 0;
  read_attribute_raw(object, name, H5T_NATIVE_LLONG, &v);
  return v;
}

std::string read_string_attribute(hid_t object, const std::string& name) {
  if (H5Aexists(object, name.c_str()) <= 0)
    throw std::runtime_error("attribute '" + name + "' is missing");
  H5Handle attr(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  H5Handle type(H5Aget_type(attr), H5Tclose, "attribute type");
  std::string s(H5Tget_size(type), '\0');
  h5_check(H5Aread(attr, type, s.data()), "reading attribute " + name);
  return s.substr(0, s.find('\0'));
}

void write_attribute(hid_t object, const std::string& name, double value) {
  write_attribute_raw(object, name, H5T_NATIVE_DOUBLE, &value);
}

void write_attribute(hid_t object, const std::string& name, long long value) {
  write_attribute_raw(object, name, H5T_NATIVE_LLONG, &value);
}

void write_attribute(hid_t object, const std::string& name, const std::string& value) {
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  h5_check(H5Tset_size(type, value.size() + 1), "string size");
  write_attribute_raw(object, name, type, value.c_str());
}

}  // namespace lbdem
