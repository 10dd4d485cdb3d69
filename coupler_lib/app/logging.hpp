#pragma once
// spdlog set-up shared by both binaries: every line is tagged with side and rank; info and
// below come from rank 0 of each side only, warnings and errors from every rank.
#include <spdlog/spdlog.h>

#include <memory>
#include <string>
#include <string_view>

namespace lbdem {

std::shared_ptr<spdlog::logger> make_logger(std::string_view side, int rank,
                                            const std::string& level);

}  // namespace lbdem
