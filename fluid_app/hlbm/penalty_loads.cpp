#include "fluid_app/hlbm/penalty_loads.hpp"

#include <stdexcept>
#include <string>

namespace lbdem::hlbm {

template <class T>
std::vector<BodyLoad> PenaltyLoads<T>::loads(const BodyField<T>& bodies, std::int64_t step) {
  const std::size_t slots = bodies.slots();
  if (by_slot_.size() < slots) by_slot_.resize(slots);
  // A body whose slot now holds another body (or none) was taken out of the field since the
  // last call; its Q and L must have gone to zero.
  for (std::size_t s = 0; s < by_slot_.size(); ++s) {
    CoveredMemory& m = by_slot_[s];
    const std::int64_t now = s < slots ? bodies.id_of(static_cast<std::int32_t>(s)) : -1;
    if (m.id < 0 || m.id == now) continue;
    if (m.covered != std::array<double, 3>{} || m.covered_moment != std::array<double, 3>{})
      throw std::logic_error(
          "PenaltyLoads: body " + std::to_string(m.id) +
          " was taken out of a fluid rank while it still covered cells there; its load would "
          "lose the momentum of that fluid (raise coupling.margin)");
    m = CoveredMemory{};
  }
  const PorousField<T>& field = bodies.field();
  const UnitConverter& units = bodies.frame().units;
  const std::size_t known = field.exchange.size();
  std::vector<BodyLoad> out;
  for (std::size_t s = 0; s < slots; ++s) {
    const std::int64_t id = bodies.id_of(static_cast<std::int32_t>(s));
    if (id < 0) continue;
    CoveredMemory& m = by_slot_[s];
    m.id = id;  // a body new in this slot starts from Q = L = 0
    const PenaltyExchange e = s < known ? field.exchange[s] : PenaltyExchange{};
    const Eigen::Vector3d& x = bodies.centre(static_cast<std::int32_t>(s));
    // The move since L^{n-1} was summed (minimum image: the centre wraps on periodic axes), and
    // the moment about x^n that Q^{n-1} had about x^{n-1}.
    Eigen::Vector3d moved;
    for (int a = 0; a < 3; ++a) moved[a] = bodies.subdomain().min_image(a, x[a] - m.centre[a]);
    const Eigen::Vector3d carried = moved.cross(Eigen::Vector3d(m.covered.data()));
    BodyLoad load;
    load.id = id;
    load.step = step;
    for (int a = 0; a < 3; ++a) {
      const double f = -e.impulse[a] + (e.covered[a] - m.covered[a]);
      const double t = -e.moment[a] + (e.covered_moment[a] - m.covered_moment[a]) + carried[a];
      load.f[a] = f * units.force();
      load.t[a] = t * units.torque();
      m.centre[a] = x[a];
    }
    m.covered = e.covered;
    m.covered_moment = e.covered_moment;
    out.push_back(load);
  }
  return out;
}

template <class T>
std::vector<typename PenaltyLoads<T>::CoveredMemory> PenaltyLoads<T>::covered_memory(
    const BodyField<T>& bodies) const {
  std::vector<CoveredMemory> out;
  for (std::size_t s = 0; s < bodies.slots(); ++s) {
    const std::int64_t id = bodies.id_of(static_cast<std::int32_t>(s));
    if (id < 0) continue;
    if (s < by_slot_.size() && by_slot_[s].id == id)
      out.push_back(by_slot_[s]);
    else
      out.push_back({id, {}, {}, {}});
  }
  return out;
}

template <class T>
void PenaltyLoads<T>::restore_covered(const BodyField<T>& bodies, const CoveredMemory& m) {
  const std::int32_t slot = bodies.slot_of(m.id);
  if (slot < 0)
    throw std::out_of_range("restore_covered: body " + std::to_string(m.id) +
                            " is not tracked on this fluid rank");
  if (by_slot_.size() <= static_cast<std::size_t>(slot))
    by_slot_.resize(static_cast<std::size_t>(slot) + 1);
  by_slot_[static_cast<std::size_t>(slot)] = m;
}

template class PenaltyLoads<double>;
template class PenaltyLoads<float>;

}  // namespace lbdem::hlbm
