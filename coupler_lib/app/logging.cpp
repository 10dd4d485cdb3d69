#include "coupler_lib/app/logging.hpp"

#include <spdlog/sinks/stdout_sinks.h>

namespace lbdem {

std::shared_ptr<spdlog::logger> make_logger(std::string_view side, int rank,
                                            const std::string& level) {
  auto sink = std::make_shared<spdlog::sinks::stderr_sink_mt>();
  auto log = std::make_shared<spdlog::logger>(std::string(side) + " " + std::to_string(rank), sink);
  log->set_pattern("[%H:%M:%S.%e] [%n] [%l] %v");
  auto lvl = spdlog::level::from_str(level);
  if (rank != 0 && lvl < spdlog::level::warn) lvl = spdlog::level::warn;
  log->set_level(lvl);
  log->flush_on(spdlog::level::info);
  return log;
}

}  // namespace lbdem
