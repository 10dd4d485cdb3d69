#include "coupler_lib/coupling/live_transport.hpp"

#include <type_traits>
#include <utility>

#include "coupler_lib/coupling/exchange.hpp"

namespace lbdem {

namespace {

// The wait of one transfer, run under the world's stall watch: the check between two tests
// also notices the other program leaving early.
ExchangeWait watched_wait(const World& world, WaitMode mode, double& waited) {
  StallWatch& stall = world.stall();
  return ExchangeWait(
      mode,
      [&world, &stall] {
        world.check_peer();
        stall.check();
      },
      &waited);
}

// Runs one transfer (`f`, given its wait) as step `step` of the stall watch.
template <class F>
auto watched(const World& world, WaitMode mode, double& waited, std::int64_t step, F&& f) {
  StallWatch& stall = world.stall();
  stall.begin(step);
  if constexpr (std::is_void_v<decltype(f(std::declval<const ExchangeWait&>()))>) {
    f(watched_wait(world, mode, waited));
    stall.end();
  } else {
    auto received = f(watched_wait(world, mode, waited));
    stall.end();
    return received;
  }
}

}  // namespace

LiveFluidTransport::LiveFluidTransport(const World& world)
    : world_(&world),
      inter_(world.inter()),
      rank_(world.rank()),
      dem_ranks_(world.peer().size),
      wait_(world.wait()),
      loads_(inter_) {}

void LiveFluidTransport::announce(const FluidLayout& layout) {
  // Fluid rank 0 broadcasts to every DEM rank (intercommunicator broadcast: the sending
  // group names MPI_ROOT on its root and MPI_PROC_NULL elsewhere).
  std::vector<double> flat = pack_layout(layout);
  unsigned long long n = flat.size();
  const int root = rank_ == 0 ? MPI_ROOT : MPI_PROC_NULL;
  MPI_Request req;
  MPI_Ibcast(&n, 1, MPI_UNSIGNED_LONG_LONG, root, inter_, &req);
  wait_request(req, wait_, [this] { world_->check_peer(); });
  MPI_Ibcast(flat.data(), static_cast<int>(n), MPI_DOUBLE, root, inter_, &req);
  wait_request(req, wait_, [this] { world_->check_peer(); });
}

std::vector<std::vector<BodyState>> LiveFluidTransport::receive_states(std::int64_t step) {
  return watched(*world_, wait_, waited_, step, [this](const ExchangeWait& wait) {
    return receive_packets<BodyState>(inter_, wait);
  });
}

void LiveFluidTransport::send_loads(std::int64_t step,
                                    const std::vector<std::vector<BodyLoad>>& per_dem_rank) {
  watched(*world_, wait_, waited_, step,
          [&](const ExchangeWait& wait) { loads_.send(per_dem_rank, wait); });
}

LiveDemTransport::LiveDemTransport(const World& world)
    : world_(&world),
      inter_(world.inter()),
      fluid_ranks_(world.peer().size),
      wait_(world.wait()),
      states_(inter_) {}

FluidLayout LiveDemTransport::receive_layout() {
  unsigned long long n = 0;
  MPI_Request req;
  MPI_Ibcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, inter_, &req);
  wait_request(req, wait_, [this] { world_->check_peer(); });
  std::vector<double> flat(n);
  MPI_Ibcast(flat.data(), static_cast<int>(n), MPI_DOUBLE, 0, inter_, &req);
  wait_request(req, wait_, [this] { world_->check_peer(); });
  return unpack_layout(flat);
}

void LiveDemTransport::send_states(std::int64_t step, std::span<const BodyState>,
                                   const std::vector<std::vector<BodyState>>& per_fluid_rank) {
  watched(*world_, wait_, waited_, step,
          [&](const ExchangeWait& wait) { states_.send(per_fluid_rank, wait); });
}

std::vector<std::vector<BodyLoad>> LiveDemTransport::receive_loads(std::int64_t step) {
  return watched(*world_, wait_, waited_, step, [this](const ExchangeWait& wait) {
    return receive_packets<BodyLoad>(inter_, wait);
  });
}

}  // namespace lbdem
