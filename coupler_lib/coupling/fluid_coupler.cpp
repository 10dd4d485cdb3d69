#include "coupler_lib/coupling/fluid_coupler.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "coupler_lib/coupling/live_transport.hpp"
#include "coupler_lib/coupling/reduce.hpp"
#include "coupler_lib/coupling/replay_transport.hpp"
#include "coupler_lib/errors.hpp"

namespace lbdem {

double stencil_margin(const Scene& scene) {
  if (!scene.fluid) return 0;
  return scene.coupling.margin * scene.fluid->dx;
}

FluidCoupler::FluidCoupler(const World& world, const FluidGeometry& geometry)
    : FluidCoupler(world.side(), std::make_unique<LiveFluidTransport>(world), geometry) {}

FluidCoupler::FluidCoupler(const SideInfo& ctx, const std::string& recording,
                           const FluidGeometry& geometry)
    : FluidCoupler(ctx.side_comm, std::make_unique<ReplayFluidTransport>(ctx, recording),
                   geometry) {}

FluidCoupler::FluidCoupler(MPI_Comm side, std::unique_ptr<FluidTransport> transport,
                           const FluidGeometry& g)
    : transport_(std::move(transport)), side_(side) {
  MPI_Comm_rank(side, &rank_);
  layout_.domain = g.domain;
  layout_.periodic = g.periodic;
  layout_.shape_radius = g.shape_radius;
  layout_.margin = g.margin;
  gather_boxes(g.mine);
  transport_->announce(layout_);
}

void FluidCoupler::gather_boxes(const Box& mine) {
  int size = 1;
  MPI_Comm_size(side_, &size);
  const double box[6] = {mine.lo[0], mine.lo[1], mine.lo[2], mine.hi[0], mine.hi[1], mine.hi[2]};
  std::vector<double> all(6 * static_cast<size_t>(size));
  MPI_Allgather(box, 6, MPI_DOUBLE, all.data(), 6, MPI_DOUBLE, side_);
  layout_.boxes.resize(static_cast<size_t>(size));
  for (size_t r = 0; r < layout_.boxes.size(); ++r)
    for (int d = 0; d < 3; ++d) {
      layout_.boxes[r].lo[d] = all[6 * r + static_cast<size_t>(d)];
      layout_.boxes[r].hi[d] = all[6 * r + 3 + static_cast<size_t>(d)];
    }
  try {
    validate_layout(layout_);
  } catch (const std::invalid_argument& e) {
    throw SideError(std::string("fluid decomposition given to the coupler: ") + e.what());
  }
}

bool FluidCoupler::announce_layout(const Box& mine) {
  const ScopedCouplingTimer timer(times_);
  const std::vector<double> before = pack_layout(layout_);
  gather_boxes(mine);
  transport_->announce(layout_);
  return pack_layout(layout_) != before;
}

FluidCoupler::~FluidCoupler() = default;

std::vector<BodyState> FluidCoupler::receive_states(std::int64_t step) {
  const ScopedCouplingTimer timer(times_);
  const auto per_dem = transport_->receive_states(step);
  count_traffic(times_, per_dem);
  source_.clear();
  std::vector<BodyState> out;
  for (size_t src = 0; src < per_dem.size(); ++src) {
    for (const BodyState& s : per_dem[src]) {
      check_packet(s.version, s.step, step, s.id, "state");
      const double reach = layout_.reach(s.shape);
      if (periodic_distance2(layout_, layout_.boxes[static_cast<size_t>(rank_)], s.x) >
          reach * reach)
        throw std::runtime_error("DEM rank " + std::to_string(src) + " sent body " +
                                 std::to_string(s.id) + " to fluid rank " + std::to_string(rank_) +
                                 ", which it cannot reach at step " + std::to_string(step) +
                                 " (the sides disagree on the layout)");
      const auto [it, fresh] = source_.emplace(s.id, static_cast<int>(src));
      if (!fresh)
        throw std::runtime_error("body " + std::to_string(s.id) + " at step " +
                                 std::to_string(step) + " came from DEM ranks " +
                                 std::to_string(it->second) + " and " + std::to_string(src) +
                                 ": a body must have exactly one owner");
      out.push_back(s);
    }
  }
  std::sort(out.begin(), out.end(),
            [](const BodyState& a, const BodyState& b) { return a.id < b.id; });
  step_ = step;
  answered_ = false;
  return out;
}

void FluidCoupler::send_loads(std::int64_t step, std::span<const BodyLoad> partials) {
  const ScopedCouplingTimer timer(times_);
  if (answered_)
    throw std::runtime_error("send_loads(" + std::to_string(step) +
                             ") without a receive_states before it: each receive_states is "
                             "answered by exactly one send_loads (last received: step " +
                             std::to_string(step_) + ")");
  answered_ = true;
  std::vector<std::vector<BodyLoad>> buckets(static_cast<size_t>(transport_->dem_ranks()));
  std::unordered_map<std::int64_t, bool> sent;
  for (const BodyLoad& p : partials) {
    const auto it = source_.find(p.id);
    if (it == source_.end())
      throw std::runtime_error("fluid rank " + std::to_string(rank_) + ": load for body " +
                               std::to_string(p.id) + " at step " + std::to_string(step) +
                               ", but this rank did not receive that body at this step");
    if (!sent.emplace(p.id, true).second)
      throw std::runtime_error("fluid rank " + std::to_string(rank_) + ": two loads for body " +
                               std::to_string(p.id) + " at step " + std::to_string(step));
    BodyLoad l = p;
    l.version = kProtocolVersion;
    l.step = step;
    buckets[static_cast<size_t>(it->second)].push_back(l);
  }
  count_traffic(times_, buckets);
  transport_->send_loads(step, buckets);
}

CouplingTimes FluidCoupler::times() const {
  CouplingTimes t = times_;
  t.idle_s = transport_->waited();
  return t;
}

}  // namespace lbdem
