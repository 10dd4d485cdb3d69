#include "coupler_lib/scene/coupling_section.hpp"

#include <string>

#include "coupler_lib/scene/scene_paths.hpp"

namespace lbdem {

CouplingParams parse_coupling(Section& s) {
  CouplingParams p;
  p.record = s.get<std::string>("record", "",
                                "HDF5 file that records every packet (relative to the scene)");
  if (!p.record.empty()) {
    p.record = resolve_scene_path(s.file(), p.record);
    check_output_file(s, "record", p.record);
  }
  p.margin = s.get<double>("margin", 2.0, "stencil margin in fluid cells", Bounds::non_negative());
  p.exchange_interval = s.get<int>("exchange_interval", 1, "fluid steps between packet exchanges",
                                   Bounds::at_least(1));
  // Both programs exchange packets after every fluid step; a coarser exchange would need the
  // DEM to hold the load over several fluid steps, which neither side implements yet.
  if (p.exchange_interval != 1)
    s.fail("exchange_interval",
           "only 1 is supported (packets are exchanged after every fluid step), got " +
               std::to_string(p.exchange_interval));
  p.output_interval = s.get<double>("output_interval", 0.0, "simulated s between outputs (0: none)",
                                    Bounds::non_negative());
  p.checkpoint_interval =
      s.get<double>("checkpoint_interval", 0.0, "simulated s between checkpoints (0: none)",
                    Bounds::non_negative());
  p.checkpoint_keep =
      s.get<int>("checkpoint_keep", 2, "checkpoints kept on disk (older ones are removed)",
                 Bounds::at_least(1));
  p.handshake_timeout =
      s.get<double>("handshake_timeout", 60.0, "wall s to wait for the other program at start",
                    Bounds::positive());
  p.stall_timeout = s.get<double>(
      "stall_timeout", 0.0,
      "wall s a side waits for the other's packets before ending the job (0: automatic, 600 s "
      "for the first two exchanges, then the larger of 60 s and 50 x the slowest exchange so far)",
      Bounds::non_negative());
  p.wait = s.choice("wait", "backoff", {"backoff", "blocking"},
                    "how a side waits for the other: backoff sleeps, blocking spins a core");
  p.overlap =
      s.get<bool>("overlap", true,
                  "the two programs compute at the same time, the fluid on body states "
                  "one fluid step older (false: they take turns; docs/coupling-overlap.md)");
  s.finish();
  return p;
}

}  // namespace lbdem
