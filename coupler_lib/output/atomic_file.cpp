#include "coupler_lib/output/atomic_file.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace lbdem {

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + tmp);
    out << text;
    if (!out) throw std::runtime_error("writing " + tmp + " failed");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace lbdem
