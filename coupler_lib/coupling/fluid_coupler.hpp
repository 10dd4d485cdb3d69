#pragma once
// The fluid program's end of the coupling.
//
//   FluidCoupler coupler(world, geometry);            // live (after connect())
//   FluidCoupler coupler(ctx, ctx.cli.replay, geometry);  // alone, fed by a recording
//   for each coupling step:
//     auto bodies = coupler.receive_states(step);    // every body that can touch my box
//     ... HLBM, momentum exchange ...
//     coupler.send_loads(step, partials);            // my partial force/torque per body
//
// receive_states returns each body once (sorted by id) even when several periodic images
// reach this rank: the fluid applies the minimum-image convention itself. send_loads takes
// partials only for the bodies of the last receive_states (each receive_states is answered by
// one send_loads); they go back to the DEM rank that sent the state, which sums the partials
// of all fluid ranks in fluid-rank order. Step labels are the programs' choice (loads may be
// labelled with the step that produced them); each receiver checks the label it was told to
// expect, so both programs must label alike.
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "coupler_lib/coupling/coupling_times.hpp"
#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/coupling/routing.hpp"
#include "coupler_lib/coupling/side_info.hpp"
#include "coupler_lib/coupling/transport.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// What the fluid side tells the coupler about itself (SI units).
struct FluidGeometry {
  Box mine;                          // this rank's subdomain (owned nodes, no ghost layer)
  Box domain;                        // the whole fluid box
  std::array<bool, 3> periodic{};    // periodic axes
  std::vector<double> shape_radius;  // bounding radius of each catalogue shape, m
  double margin = 0;                 // stencil margin, m: stencil_margin(scene)
};

// coupling.margin fluid cells times dx.
double stencil_margin(const Scene& scene);

class FluidCoupler {
 public:
  // Live. Collective over both programs (the DEM side constructs its DemCoupler).
  FluidCoupler(const World& world, const FluidGeometry& geometry);
  // Replay from a recording. Collective over the fluid ranks.
  FluidCoupler(const SideInfo& ctx, const std::string& recording, const FluidGeometry& geometry);
  ~FluidCoupler();

  std::vector<BodyState> receive_states(std::int64_t step);
  void send_loads(std::int64_t step, std::span<const BodyLoad> partials);

  // At an in-run rebalancing step (live or replayed; collective over both programs live):
  // this rank's subdomain from now on, new or unchanged, and the layout of all of them goes to
  // the DEM side (DemCoupler::follow_layout). Returns whether any rank's box changed: the DEM
  // then sends the states of its last step again, routed by the new boxes, and the next
  // receive_states (of that same step) takes them.
  bool announce_layout(const Box& mine);

  const FluidLayout& layout() const { return layout_; }  // every fluid rank's box
  int rank() const { return rank_; }
  // Time spent in this coupler so far, and how much of it was waiting for the DEM.
  CouplingTimes times() const;

 private:
  FluidCoupler(MPI_Comm side, std::unique_ptr<FluidTransport> transport,
               const FluidGeometry& geometry);

  void gather_boxes(const Box& mine);  // every rank's box into layout_, validated

  std::unique_ptr<FluidTransport> transport_;
  CouplingTimes times_;
  MPI_Comm side_;
  int rank_ = 0;
  FluidLayout layout_;
  std::int64_t step_ = -1;                        // step of the last receive_states
  bool answered_ = true;                          // send_loads answered it
  std::unordered_map<std::int64_t, int> source_;  // body id -> DEM rank that sent it
};

}  // namespace lbdem
