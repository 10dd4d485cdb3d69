#pragma once
// Bit-for-bit comparison of recorded and replayed packets, for --replay.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"

namespace lbdem {

// Both lists sorted by body id. Returns nothing when every field of every packet has the
// same bits, otherwise the first difference: step, body, quantity and both values, e.g.
// "step 12, body 3, f[1]: recorded 1.2500000000000000e-03, replayed 1.2500000000000002e-03".
std::optional<std::string> first_mismatch(std::int64_t step, std::span<const BodyState> recorded,
                                          std::span<const BodyState> replayed);
std::optional<std::string> first_mismatch(std::int64_t step, std::span<const BodyLoad> recorded,
                                          std::span<const BodyLoad> replayed);

// The recorded loads of the bodies `owned`, in that order, from all the loads `recorded` at a
// step (a recording or a DEM journal, named `source` in the error). Throws std::runtime_error
// when a body has none.
std::vector<BodyLoad> loads_of(std::span<const std::int64_t> owned,
                               std::span<const BodyLoad> recorded, const std::string& source,
                               std::int64_t step);

}  // namespace lbdem
