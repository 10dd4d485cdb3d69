#pragma once
// Reading a small HDF5 file whole, serially, on each rank that needs it (no MPI-IO): the bodies
// file of a scene (coupler_lib/scene/bodies_file.hpp). No HDF5 type appears here, so a layer
// that reads through this header does not compile against HDF5.
#include <cstddef>
#include <string>
#include <vector>

namespace lbdem {

// One dataset at the root of a file.
struct H5Array {
  std::string name;
  std::vector<std::size_t> dims;  // e.g. {N, 3}; {} for a scalar
  bool text = false;              // a string dataset: values in `strings`, `numbers` empty
  std::vector<double> numbers;    // row-major, converted to double by HDF5 (integers too)
  std::vector<std::string> strings;
};

// Every object at the root of `path`, in name order. Throws std::runtime_error with a message
// that starts with `path: ` for a file that is missing, unreadable or not HDF5, and for a root
// object that is not a dataset of numbers or strings.
std::vector<H5Array> read_root_datasets(const std::string& path);

}  // namespace lbdem
