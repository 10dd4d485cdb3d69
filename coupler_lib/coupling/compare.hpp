#pragma once
// Bit-for-bit comparison of recorded and replayed packets, for --replay.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "coupler_lib/coupling/packets.hpp"

namespace lbdem {

// Both lists sorted by body id. Returns nothing when every field of every packet has the
// same bits, otherwise the first difference: step, body, quantity and both values, e.g.
// "step 12, body 3, f[1]: recorded 1.2500000000000000e-03, replayed 1.2500000000000002e-03".
std::optional<std::string> first_mismatch(std::int64_t step, std::span<const BodyState> recorded,
                                          std::span<const BodyState> replayed);
std::optional<std::string> first_mismatch(std::int64_t step, std::span<const BodyLoad> recorded,
                                          std::span<const BodyLoad> replayed);

}  // namespace lbdem
