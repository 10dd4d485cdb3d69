#pragma once
// The DEM program's end of the coupling.
//
//   DemCoupler coupler(world, ctx.scene);             // live (after connect()); records
//                                                     // when coupling.record is set (each
//                                                     // rank its own part, recording.hpp)
//   DemCoupler coupler(ctx, ctx.cli.replay);          // alone, fed by a recording
//   for each coupling step:
//     coupler.send_states(step, owned);               // every body this rank owns now
//     auto loads = coupler.receive_loads(step);       // loads[i] is on owned[i]
//     ... n_DEM substeps with the loads held constant ...
//
// Ownership may change between steps (LAMMPS migrates bodies): each call takes whatever
// this rank owns at that moment, and the load on a body comes back to the rank that sent
// its state. The partials of several fluid ranks are summed in fluid-rank order, so the
// result does not depend on message arrival (reduce.hpp).
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "coupler_lib/coupling/coupling_times.hpp"
#include "coupler_lib/coupling/journal.hpp"
#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/coupling/routing.hpp"
#include "coupler_lib/coupling/side_info.hpp"
#include "coupler_lib/coupling/transport.hpp"
#include "coupler_lib/coupling/world.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

class DemCoupler {
 public:
  // Live. Collective over both programs (the fluid side constructs its FluidCoupler).
  // `journal`: the path of the journal of every exchange kept for checkpoints, of which this
  // rank writes its part (journal.hpp; the DEM half of a checkpoint holds the parts up to its
  // step, docs/reliability.md); empty: none.
  DemCoupler(const World& world, const Scene& scene, const std::string& journal = {});
  // Replay from a recording. Collective over the DEM ranks.
  DemCoupler(const SideInfo& ctx, const std::string& recording);
  // A restart's replay of this rank's part of a checkpoint's journal (no communication).
  static std::unique_ptr<DemCoupler> replaying_journal(const SideInfo& ctx,
                                                       const std::string& part);
  ~DemCoupler();

  // Collective over both programs (live) or over the DEM ranks (replay).
  void send_states(std::int64_t step, std::span<const BodyState> owned);
  // One load per body of the last send_states, in the same order. `step` is the label the
  // fluid side gave its loads (checked on every packet).
  std::vector<BodyLoad> receive_loads(std::int64_t step);

  // Journal entries for exchanges that did not go through this coupler (a restart replays
  // its checkpoint's steps before the live exchanges resume). This rank's part only.
  void journal_states(std::int64_t step, std::span<const BodyState> owned);
  void journal_loads(std::int64_t step, std::span<const BodyLoad> loads);
  // Writes this rank's part of the journal to disk and returns its path (empty without one).
  std::string flush_journal();

  // Live, at an in-run rebalancing step of the fluid (Schedule::rebalance_at), after the
  // step's send_states; collective over both programs. Takes the layout the fluid announced
  // (FluidCoupler::announce_layout); when it changed, the states of that send_states go again,
  // routed by it, for the fluid's new blocks to embed (not to the recording or the journal,
  // which hold each step once). Returns whether it changed.
  bool follow_layout();

  // The decomposition the fluid side announced (or the recorded one in a replay).
  const FluidLayout& fluid_layout() const { return layout_; }
  // Time spent in this coupler so far, and how much of it was waiting for the fluid.
  CouplingTimes times() const;

 private:
  DemCoupler(MPI_Comm side, std::unique_ptr<DemTransport> transport);
  // The copies of `states` for each fluid rank whose box a state reaches (layout_).
  std::vector<std::vector<BodyState>> route(std::span<const BodyState> states) const;

  std::unique_ptr<DemTransport> transport_;
  CouplingTimes times_;
  // coupling.record: this rank's part of the recording, written as the journal is (journal.hpp)
  std::unique_ptr<JournalWriter> recorder_;
  std::unique_ptr<JournalWriter> journal_;
  MPI_Comm side_;
  FluidLayout layout_;
  std::int64_t step_ = -1;       // step of the last send_states
  bool answered_ = true;         // receive_loads answered it
  std::vector<BodyState> sent_;  // what was sent at step_
};

}  // namespace lbdem
