#pragma once
// The live transport: packets go to the other program over the intercommunicator
// (exchange.hpp: one-way transfers, sends completed in the background), waiting with the world's
// wait mode and watching for the other program leaving early (World::check_peer) or going silent
// (World::stall).
#include "coupler_lib/coupling/exchange.hpp"
#include "coupler_lib/coupling/transport.hpp"
#include "coupler_lib/coupling/world.hpp"

namespace lbdem {

class LiveFluidTransport : public FluidTransport {
 public:
  explicit LiveFluidTransport(const World& world);
  int dem_ranks() const override { return dem_ranks_; }
  void announce(const FluidLayout& layout) override;
  std::vector<std::vector<BodyState>> receive_states(std::int64_t step) override;
  void send_loads(std::int64_t step,
                  const std::vector<std::vector<BodyLoad>>& per_dem_rank) override;
  double waited() const override { return waited_; }

 private:
  double waited_ = 0;
  const World* world_;
  MPI_Comm inter_;
  int rank_;
  int dem_ranks_;
  WaitMode wait_;
  PacketSender loads_;
};

class LiveDemTransport : public DemTransport {
 public:
  explicit LiveDemTransport(const World& world);
  int fluid_ranks() const override { return fluid_ranks_; }
  FluidLayout receive_layout() override;
  void send_states(std::int64_t step, std::span<const BodyState> owned,
                   const std::vector<std::vector<BodyState>>& per_fluid_rank) override;
  std::vector<std::vector<BodyLoad>> receive_loads(std::int64_t step) override;
  double waited() const override { return waited_; }

 private:
  double waited_ = 0;
  const World* world_;
  MPI_Comm inter_;
  int fluid_ranks_;
  WaitMode wait_;
  PacketSender states_;
};

}  // namespace lbdem
