#pragma once
// Summing the partial loads of one body from several fluid ranks.
//
// Floating-point addition is not associative, so the sum is taken in a fixed order, by
// source (fluid rank) ascending, starting from zero: the result does not depend on which
// message arrived first, and a replay that sums the same partials reproduces it bit for bit.
#include <cstdint>
#include <span>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"

namespace lbdem {

// Result i is the load on sent[i] (zero if no source sent a partial for it), stamped with
// `step`. Throws std::runtime_error when a partial has another protocol version or step,
// names a body not in `sent`, or appears twice from one source.
std::vector<BodyLoad> reduce_loads(std::span<const BodyState> sent,
                                   const std::vector<std::vector<BodyLoad>>& per_source,
                                   std::int64_t step);

// Throws std::runtime_error naming `what` when a packet has another version or step.
void check_packet(std::uint32_t version, std::int64_t packet_step, std::int64_t step,
                  std::int64_t id, const char* what);

}  // namespace lbdem
