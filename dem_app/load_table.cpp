#include "dem_app/load_table.hpp"

#include <stdexcept>
#include <string>

namespace lbdem {

LoadTable::LoadTable(std::int64_t bodies, int rank, int ranks)
    : bodies_(bodies), rank_(rank), ranks_(ranks) {
  if (ranks < 1 || rank < 0 || rank >= ranks || bodies < 0)
    throw std::invalid_argument("LoadTable: bad rank layout");
  const std::int64_t mine = bodies > rank ? (bodies - 1 - rank) / ranks + 1 : 0;
  entries_.resize(static_cast<std::size_t>(mine));
}

std::size_t LoadTable::index(std::int64_t id) const {
  if (id < 0 || id >= bodies_ || !is_home(id))
    throw std::out_of_range("load for unknown body " + std::to_string(id));
  return static_cast<std::size_t>(id / ranks_);
}

void LoadTable::update(const LoadUpdate& u) {
  Entry& e = entries_[index(u.id)];
  if (u.kind != 0) {
    for (int d = 0; d < 3; ++d) e.extra[d] = u.f[d];
    return;
  }
  if (e.run != run_ + 1) {  // the first load set for the next run: the current one is F_old
    for (int d = 0; d < 3; ++d) {
      e.previous_f[d] = e.load_f[d];
      e.previous_t[d] = e.load_t[d];
    }
    e.run = run_ + 1;
  }
  for (int d = 0; d < 3; ++d) {
    e.load_f[d] = u.f[d];
    e.load_t[d] = u.t[d];
  }
}

AppliedLoad LoadTable::applied(std::int64_t id, bool kick) const {
  const Entry& e = entries_[index(id)];
  const bool set_now = e.run == run_;  // else the load is that of an earlier run, unchanged
  AppliedLoad a;
  for (int d = 0; d < 3; ++d) {
    a.force[d] = e.load_f[d] + e.extra[d];
    a.torque[d] = e.load_t[d];
    const double old_f = set_now ? e.previous_f[d] : e.load_f[d];
    const double old_t = set_now ? e.previous_t[d] : e.load_t[d];
    a.kick_force[d] = kick ? 0.5 * (e.load_f[d] - old_f) : 0.0;
    a.kick_torque[d] = kick ? 0.5 * (e.load_t[d] - old_t) : 0.0;
  }
  return a;
}

}  // namespace lbdem
