#pragma once
// The hydrodynamic force and torque on every body of a rank's BodyField from the penalization
// itself (docs/method.md Eqs. (13)-(15), docs/method-loads.md):
//   F_k = -P_k^n + (Q_k^n - Q_k^{n-1}),
//   T_k = -M_k^n + (L_k^n - L_k^{n-1}) + (x_k^n - x_k^{n-1}) x Q_k^{n-1},
// with the sums the kernel wrote in the last step (PorousField::exchange) over the cells this
// rank owns. M and L are summed about the centre x^n of the step; the last term carries L^{n-1},
// summed about x^{n-1}, to x^n, so that a body that moves conserves angular momentum with the
// fluid (docs/method-loads.md section 7). What it keeps from one step to the next is Q, L and
// x per body, which checkpoints save (covered_memory) and restarts put back (restore_covered).
//
// Use (one per fluid rank, next to its BodyField):
//   hlbm::PenaltyLoads<T> loads;
//   each step: bodies.update(states);  solver.step();
//              std::vector<BodyLoad> partial = loads.loads(bodies, step);
#include <array>
#include <cstdint>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "fluid_app/hlbm/body_field.hpp"

namespace lbdem::hlbm {

template <class T>
class PenaltyLoads {
 public:
  // One partial load per body of the last update (SI; torque about the centre of mass), in
  // slot order. Call once per step, after the solver step: it keeps Q^n for the next.
  // Throws std::logic_error if a body left the rank while it still covered some of its cells
  // (its last Q could then not be returned; the coupler's reach prevents it).
  std::vector<BodyLoad> loads(const BodyField<T>& bodies, std::int64_t step);

  // Q^n and L^n of this rank's cells for one body, and the centre x^n (lattice coordinates)
  // L^n is summed about.
  struct CoveredMemory {
    std::int64_t id = -1;
    std::array<double, 3> covered{}, covered_moment{}, centre{};
  };
  // One entry per body tracked by `bodies` (zero for a body no load was taken of yet).
  std::vector<CoveredMemory> covered_memory(const BodyField<T>& bodies) const;
  // Sets it for a body tracked by `bodies` (a restart, after its first update); throws
  // std::out_of_range when the body is not tracked there.
  void restore_covered(const BodyField<T>& bodies, const CoveredMemory& m);

 private:
  std::vector<CoveredMemory> by_slot_;  // by BodyField slot; id -1: nothing kept
};

extern template class PenaltyLoads<double>;
extern template class PenaltyLoads<float>;

}  // namespace lbdem::hlbm
