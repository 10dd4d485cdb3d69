#include "coupler_lib/output/series_resume.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace lbdem {

void cut_series_to(const std::string& path, long long bytes) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || static_cast<long long>(size) < bytes)
    throw std::runtime_error(
        path + ": the series holds " +
        (ec ? std::string("nothing (missing)") : std::to_string(size) + " bytes") +
        ", the checkpoint expects at least " + std::to_string(bytes) +
        "; restore the output folder of the stopped run");
  std::filesystem::resize_file(path, static_cast<std::uintmax_t>(bytes), ec);
  if (ec) throw std::runtime_error(path + ": cannot cut the series back: " + ec.message());
}

}  // namespace lbdem
