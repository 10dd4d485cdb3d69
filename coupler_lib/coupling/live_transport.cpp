#include "coupler_lib/coupling/live_transport.hpp"

#include "coupler_lib/coupling/exchange.hpp"

namespace lbdem {

namespace {

// One exchange whose waits for the other program run under the world's stall watch.
template <class T>
std::vector<std::vector<T>> watched(const World& world, WaitMode mode, double& waited,
                                    std::int64_t step, const std::vector<std::vector<T>>& send) {
  StallWatch& stall = world.stall();
  stall.begin(step);
  auto received = exchange(world.inter(), send,
                           ExchangeWait(
                               mode,
                               [&world, &stall] {
                                 world.check_peer();
                                 stall.check();
                               },
                               &waited));
  stall.end();
  return received;
}

}  // namespace

LiveFluidTransport::LiveFluidTransport(const World& world)
    : world_(&world),
      inter_(world.inter()),
      rank_(world.rank()),
      dem_ranks_(world.peer().size),
      wait_(world.wait()) {}

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
  return watched(*world_, wait_, waited_, step,
                 std::vector<std::vector<BodyState>>(static_cast<size_t>(dem_ranks_)));
}

void LiveFluidTransport::send_loads(std::int64_t step,
                                    const std::vector<std::vector<BodyLoad>>& per_dem_rank) {
  watched(*world_, wait_, waited_, step, per_dem_rank);
}

LiveDemTransport::LiveDemTransport(const World& world)
    : world_(&world), inter_(world.inter()), fluid_ranks_(world.peer().size), wait_(world.wait()) {}

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
  watched(*world_, wait_, waited_, step, per_fluid_rank);
}

std::vector<std::vector<BodyLoad>> LiveDemTransport::receive_loads(std::int64_t step) {
  return watched(*world_, wait_, waited_, step,
                 std::vector<std::vector<BodyLoad>>(static_cast<size_t>(fluid_ranks_)));
}

}  // namespace lbdem
