#pragma once
// Momentum audit of a triply periodic coupled run (docs/method-loads.md): a CSV, written by
// fluid rank 0 at the coupling output steps, of
//   step, time_s,
//   fluid_px, fluid_py, fluid_pz:       momentum of the fluid outside the bodies, J - sum_k Q_k
//   bodies_px, bodies_py, bodies_pz:    sum_k m_k v_k of the bodies (states from dem_app)
//   applied_px, applied_py, applied_pz: impulse of all external forces since the start:
//                                       the uniform force on every node plus the bodies' net
//                                       weight W (DEM side), integrated over the steps
// all in N s. With the exact feed-forward force the fluid's and the bodies' external forces
// cancel and fluid + bodies stays at its initial value to round-off; with the controller the
// change equals `applied`. tools/momentum_audit.py checks it.
#include <array>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "coupler_lib/coupling/packets.hpp"
#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/scene.hpp"
#include "fluid_app/solver/fluid_solver.hpp"

namespace lbdem {

class MomentumAudit {
 public:
  // Every fluid rank constructs it (the rows are collective); rank 0 of `comm` writes.
  // net_weight: W = sum_k (rho_k - rho_f) V_k g, N.
  // `resume_bytes` >= 0: continue a restarted run's audit, cut back to that length.
  MomentumAudit(const std::string& path, const Scene& scene, const std::vector<Shape>& shapes,
                std::array<double, 3> net_weight, MPI_Comm comm, long long resume_bytes = -1);

  // Collective, after a step. `states`: the bodies this rank received after the step (each
  // body is counted on the rank whose interior box holds its centre); the covered fluid Q is
  // the solver's porous-field sums of the step just taken.
  template <class T>
  void write(std::int64_t step, double time, const FluidSolver<T>& solver,
             std::span<const BodyState> states);

  const std::string& path() const { return path_; }
  // Bytes on disk so far (rank 0; 0 elsewhere), for checkpoints.
  long long bytes();

 private:
  std::string path_;
  const Scene& scene_;
  std::vector<double> volume_;  // by shape, m^3
  std::array<double, 3> weight_;
  MPI_Comm comm_;
  int rank_ = 0;
  std::ofstream out_;
};

}  // namespace lbdem
