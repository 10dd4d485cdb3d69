#include "coupler_lib/coupling/reduce.hpp"

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace lbdem {

void check_packet(std::uint32_t version, std::int64_t packet_step, std::int64_t step,
                  std::int64_t id, const char* what) {
  if (version != kProtocolVersion)
    throw std::runtime_error(std::string(what) + " packet for body " + std::to_string(id) +
                             " has protocol version " + std::to_string(version) + ", expected " +
                             std::to_string(kProtocolVersion));
  if (packet_step != step)
    throw std::runtime_error(std::string(what) + " packet for body " + std::to_string(id) +
                             " belongs to step " + std::to_string(packet_step) +
                             ", expected step " + std::to_string(step) +
                             " (the two sides are out of step)");
}

std::vector<BodyLoad> reduce_loads(std::span<const BodyState> sent,
                                   const std::vector<std::vector<BodyLoad>>& per_source,
                                   std::int64_t step) {
  std::unordered_map<std::int64_t, size_t> index;
  index.reserve(sent.size());
  std::vector<BodyLoad> out(sent.size());
  for (size_t i = 0; i < sent.size(); ++i) {
    index.emplace(sent[i].id, i);
    out[i].id = sent[i].id;
    out[i].step = step;
  }
  std::vector<std::int64_t> seen_from(sent.size(), -1);
  for (size_t src = 0; src < per_source.size(); ++src) {
    for (const BodyLoad& p : per_source[src]) {
      check_packet(p.version, p.step, step, p.id, "load");
      const auto it = index.find(p.id);
      if (it == index.end())
        throw std::runtime_error("fluid rank " + std::to_string(src) + " sent a load for body " +
                                 std::to_string(p.id) + " at step " + std::to_string(step) +
                                 ", but this DEM rank did not send that body");
      if (seen_from[it->second] == static_cast<std::int64_t>(src))
        throw std::runtime_error("fluid rank " + std::to_string(src) + " sent two loads for body " +
                                 std::to_string(p.id) + " at step " + std::to_string(step));
      seen_from[it->second] = static_cast<std::int64_t>(src);
      BodyLoad& r = out[it->second];
      for (int d = 0; d < 3; ++d) {
        r.f[d] += p.f[d];
        r.t[d] += p.t[d];
      }
    }
  }
  return out;
}

}  // namespace lbdem
