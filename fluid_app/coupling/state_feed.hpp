#pragma once
// Which body states the fluid applies before each lattice step, and when it asks dem_app for
// them (docs/coupling-overlap.md).
//
// Without overlap, step n + 1 runs on the states of step n: the fluid sends the loads of
// step n, waits while dem_app integrates, receives the states of step n. With overlap
// (coupling.overlap), step n + 1 runs on the states of step n - 1, received before the loads
// of step n are sent, so dem_app integrates step n while the fluid runs step n + 1. The order
// of the exchanges is the one dem_app already follows (states n - 1, loads n, states n, ...),
// so the DEM loop and the recording are the same in both modes. At a `sync` step (the
// momentum audit's output steps) the fluid also waits for the states of that step.
#include <cstdint>
#include <span>
#include <vector>

#include "coupler_lib/coupling/fluid_coupler.hpp"

namespace lbdem {

class StateFeed {
 public:
  StateFeed(FluidCoupler& coupler, bool overlap) : coupler_(&coupler), overlap_(overlap) {}

  // The states before the first step (`step`: the step the run starts from, 0 or that of
  // the checkpoint it restarts from).
  const std::vector<BodyState>& start(std::int64_t step = 0);
  // After lattice step `step`: send its loads (with overlap, after receiving the states of
  // step - 1, which the DEM sent while this step ran).
  void send(std::int64_t step, std::span<const BodyLoad> loads);
  // The states to apply before step + 1; `fresh()` tells whether they changed since the last
  // call. With `sync`, or without overlap, these are the states of `step` itself.
  const std::vector<BodyState>& next(std::int64_t step, bool sync);
  bool fresh() const { return fresh_; }
  // At the end of the run: receive what dem_app still sends (its states up to `step`).
  void finish(std::int64_t step);

 private:
  void receive(std::int64_t step);

  FluidCoupler* coupler_;
  bool overlap_;
  std::vector<BodyState> held_;  // the newest states received
  std::int64_t received_ = -1;   // their step
  bool pending_ = false;         // received since the last next()
  bool fresh_ = false;           // the last next() returned states not returned before
};

}  // namespace lbdem
