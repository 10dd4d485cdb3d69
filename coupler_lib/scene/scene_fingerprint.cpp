#include "coupler_lib/scene/scene_fingerprint.hpp"

#include <array>
#include <string_view>

namespace lbdem {

bool may_change_at_restart(const std::string& key_path) {
  // Where the run stops, what it writes and how it reports; none of them is state. The fluid's
  // layout neither: the checkpoint holds the global lattice, and another layout changes the
  // loads only by the order of their sums (round-off, as another fluid rank count does).
  static constexpr std::array<std::string_view, 11> kExact = {"time.end",
                                                              "time.progress_interval",
                                                              "log_level",
                                                              "coupling.record",
                                                              "coupling.checkpoint_interval",
                                                              "coupling.checkpoint_keep",
                                                              "coupling.stall_timeout",
                                                              "fluid.decomposition",
                                                              "fluid.covered_cell_weight",
                                                              "fluid.rebalance_above",
                                                              "fluid.rebalance_interval"};
  for (const auto k : kExact)
    if (key_path == k) return true;
  // The stability watches' limits too: a run stopped by a watch may continue with a limit the
  // user judged too strict.
  static constexpr std::array<std::string_view, 7> kPrefixes = {"fluid.output",
                                                                "dem.output",
                                                                "coupling.output_interval",
                                                                "coupling.wait",
                                                                "coupling.handshake_timeout",
                                                                "fluid.stability",
                                                                "dem.max_overlap"};
  for (const auto p : kPrefixes)
    if (key_path.rfind(p, 0) == 0) return true;
  return false;
}

std::uint64_t scene_fingerprint(const Scene& scene) {
  std::string text;
  if (scene.source)
    for (const auto& k : scene.source->resolved)
      if (!may_change_at_restart(k.path)) text += k.path + "=" + k.value + "\n";
  return fnv1a(text);
}

}  // namespace lbdem
