#include "coupler_lib/output/hdf5_read.hpp"

#include <algorithm>
#include <stdexcept>

#include "coupler_lib/output/hdf5_handle.hpp"

namespace lbdem {

namespace {

std::vector<std::string> root_names(hid_t file, const std::string& path) {
  H5G_info_t info;
  h5_check(H5Gget_info(file, &info), path + ": listing the root group");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t n =
        H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (n < 0)
      throw std::runtime_error(path + ": cannot read the name of root object " + std::to_string(i));
    std::string name(static_cast<size_t>(n) + 1, '\0');
    H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<size_t>(n));
    names.push_back(name);
  }
  return names;
}

void read_strings(hid_t set, hid_t file_type, hid_t space, size_t count, H5Array& a,
                  const std::string& where) {
  a.strings.reserve(count);
  if (H5Tis_variable_str(file_type) > 0) {
    H5Handle mem(H5Tcopy(H5T_C_S1), H5Tclose, where);
    h5_check(H5Tset_size(mem, H5T_VARIABLE), where);
    h5_check(H5Tset_cset(mem, H5Tget_cset(file_type)), where);  // h5py writes UTF-8
    std::vector<char*> raw(count, nullptr);
    h5_check(H5Dread(set, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()), where);
    for (char* s : raw) a.strings.emplace_back(s ? s : "");
    H5Dvlen_reclaim(mem, space, H5P_DEFAULT, raw.data());
    return;
  }
  const size_t width = H5Tget_size(file_type);
  H5Handle mem(H5Tcopy(H5T_C_S1), H5Tclose, where);
  h5_check(H5Tset_size(mem, width), where);
  h5_check(H5Tset_cset(mem, H5Tget_cset(file_type)), where);
  std::vector<char> raw(count * width);
  h5_check(H5Dread(set, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()), where);
  for (size_t i = 0; i < count; ++i) {
    std::string s(raw.data() + i * width, width);
    s.erase(std::find(s.begin(), s.end(), '\0'), s.end());  // null-padded
    s.erase(s.find_last_not_of(' ') + 1);                   // space-padded
    a.strings.push_back(s);
  }
}

}  // namespace

std::vector<H5Array> read_root_datasets(const std::string& path) {
  const QuietHdf5 quiet;
  if (H5Fis_hdf5(path.c_str()) <= 0)
    throw std::runtime_error(path +
                             ": cannot open it as an HDF5 file (missing, unreadable or "
                             "not HDF5)");
  H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "opening " + path);
  std::vector<H5Array> out;
  for (const auto& name : root_names(file, path)) {
    const std::string where = path + ": dataset '" + name + "'";
    const hid_t id = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    if (id < 0)
      throw std::runtime_error(path + ": '" + name +
                               "' is not a dataset (groups are not read; every field is a "
                               "dataset at the root)");
    H5Handle set(id, H5Dclose, where);
    H5Handle type(H5Dget_type(set), H5Tclose, where);
    H5Handle space(H5Dget_space(set), H5Sclose, where);
    H5Array a;
    a.name = name;
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(static_cast<size_t>(std::max(rank, 0)));
    H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    size_t count = 1;
    for (hsize_t d : dims) {
      a.dims.push_back(static_cast<size_t>(d));
      count *= static_cast<size_t>(d);
    }
    const H5T_class_t cls = H5Tget_class(type);
    if (cls == H5T_INTEGER || cls == H5T_FLOAT) {
      a.numbers.resize(count);
      h5_check(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, a.numbers.data()),
               "reading " + where);
    } else if (cls == H5T_STRING) {
      a.text = true;
      read_strings(set, type, space, count, a, "reading " + where);
    } else {
      throw std::runtime_error(where + ": expected numbers or strings");
    }
    out.push_back(std::move(a));
  }
  return out;
}

}  // namespace lbdem
