#pragma once
// The `coupling:` section: what both sides agree on for exchanging packets, and the cadence
// of exchange, output and checkpoints (turned into fluid steps by make_schedule).
#include <string>

#include "coupler_lib/scene/choices.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct CouplingParams {
  std::string record;          // HDF5 file recording every packet; empty = no recording
  double margin = 2.0;         // stencil margin in fluid cells added to a body's bounding sphere
  int exchange_interval = 1;   // outer (fluid) steps between two packet exchanges
  double output_interval = 0;  // simulated s between outputs; 0 = no periodic output
  double checkpoint_interval = 0;     // simulated s between checkpoints; 0 = no checkpoints
  int checkpoint_keep = 2;            // checkpoints kept on disk, newest first
  double handshake_timeout = 60;      // wall s a side waits for the other at the handshake
  double stall_timeout = 0;           // wall s without packets before the job ends; 0 = automatic
  WaitMode wait = WaitMode::backoff;  // how a waiting side waits: sleeps (backoff) or spins
  // The DEM integrates step n while the fluid runs step n + 1 on the body states of step
  // n - 1 (one fluid step older than without it): docs/coupling-overlap.md.
  bool overlap = false;
};

const MappingSchema& coupling_schema();
CouplingParams parse_coupling(Section& s);

}  // namespace lbdem
