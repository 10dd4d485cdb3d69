#include "coupler_lib/scene/coupling_section.hpp"

#include <string>

#include "coupler_lib/scene/scene_paths.hpp"

namespace lbdem {

const MappingSchema& coupling_schema() {
  static const MappingSchema m{
      "coupling",
      "fluid-DEM packet exchange",
      {key::text("record", "HDF5 file that records every packet (relative to the scene)")
           .or_default(""),
       key::number("margin", "stencil margin in fluid cells")
           .or_default(2.0)
           .within(Bounds::non_negative()),
       // Both programs exchange packets after every fluid step; a coarser exchange would need
       // the DEM to hold the load over several fluid steps, which neither side implements yet.
       key::integer("exchange_interval",
                    "fluid steps between packet exchanges (only 1 is supported)")
           .or_default(1)
           .within(Bounds::closed(1, 1)),
       key::number("output_interval", "simulated s between outputs (0: none)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::number("checkpoint_interval", "simulated s between checkpoints (0: none)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::integer("checkpoint_keep", "checkpoints kept on disk (older ones are removed)")
           .or_default(2)
           .within(Bounds::at_least(1)),
       key::number("handshake_timeout", "wall s to wait for the other program at start")
           .or_default(60.0)
           .within(Bounds::positive())
           .in("s"),
       key::number("stall_timeout",
                   "wall s a side waits for the other's packets before ending the job (0: "
                   "automatic, 600 s for the first two exchanges, then the larger of 60 s and 50 "
                   "x the slowest exchange so far)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::choice("wait", words_of(kWaitModeWords),
                   "how a side waits for the other: backoff sleeps, blocking spins a core")
           .or_default("backoff"),
       key::boolean("overlap",
                    "the two programs compute at the same time, the fluid on body states one "
                    "fluid step older (false: they take turns; docs/coupling-overlap.md)")
           .or_default(true)}};
  return m;
}

CouplingParams parse_coupling(Section& s) {
  CouplingParams p;
  p.record = s.get<std::string>("record");
  if (!p.record.empty()) {
    p.record = resolve_scene_path(s.file(), p.record);
    check_output_file(s, "record", p.record);
  }
  p.margin = s.get<double>("margin");
  p.exchange_interval = s.get<int>("exchange_interval");
  p.output_interval = s.get<double>("output_interval");
  p.checkpoint_interval = s.get<double>("checkpoint_interval");
  p.checkpoint_keep = s.get<int>("checkpoint_keep");
  p.handshake_timeout = s.get<double>("handshake_timeout");
  p.stall_timeout = s.get<double>("stall_timeout");
  p.wait = value_of(kWaitModeWords, s.choice("wait"));
  p.overlap = s.get<bool>("overlap");
  s.finish();
  return p;
}

}  // namespace lbdem
