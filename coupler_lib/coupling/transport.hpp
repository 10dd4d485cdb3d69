#pragma once
// How packets reach the other side. The couplers (fluid_coupler.hpp, dem_coupler.hpp) do
// routing, checking and reduction; a transport only moves packets, so the live run, the
// recording run and a replay share one code path.
//   live   (live_transport.hpp):   the other program over the intercommunicator;
//   replay (replay_transport.hpp): a recording stands in for the other program, and what
//                                  this side sends is compared with what was recorded.
#include <cstdint>
#include <span>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/coupling/routing.hpp"

namespace lbdem {

// The fluid side's view of the DEM program.
class FluidTransport {
 public:
  virtual ~FluidTransport() = default;
  virtual int dem_ranks() const = 0;
  // Collective over the fluid ranks: make the decomposition known to the DEM side.
  virtual void announce(const FluidLayout& layout) = 0;
  // The states each DEM rank sent to this fluid rank, by DEM rank.
  virtual std::vector<std::vector<BodyState>> receive_states(std::int64_t step) = 0;
  // This rank's partial loads, bucketed by the DEM rank that sent the body's state.
  virtual void send_loads(std::int64_t step,
                          const std::vector<std::vector<BodyLoad>>& per_dem_rank) = 0;
  // Wall seconds spent waiting for the other program so far (0 in a replay).
  virtual double waited() const { return 0; }
};

// The DEM side's view of the fluid program.
class DemTransport {
 public:
  virtual ~DemTransport() = default;
  virtual int fluid_ranks() const = 0;
  // Collective over the DEM ranks: the decomposition the fluid side announced.
  virtual FluidLayout receive_layout() = 0;
  // `owned`: every body this DEM rank owns; `per_fluid_rank`: the routed copies.
  virtual void send_states(std::int64_t step, std::span<const BodyState> owned,
                           const std::vector<std::vector<BodyState>>& per_fluid_rank) = 0;
  // The partial loads each fluid rank sent back, by fluid rank.
  virtual std::vector<std::vector<BodyLoad>> receive_loads(std::int64_t step) = 0;
  // Wall seconds spent waiting for the other program so far (0 in a replay).
  virtual double waited() const { return 0; }
};

}  // namespace lbdem
