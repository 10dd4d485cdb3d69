#pragma once
// Momentum audit of a triply periodic coupled run (docs/method-loads.md): a CSV, written by
// fluid rank 0 at the coupling output steps, of
//   step, time_s,
//   fluid_px, fluid_py, fluid_pz:       momentum of the fluid outside the bodies, J - sum_k Q_k
//   bodies_px, bodies_py, bodies_pz:    sum_k m_k v_k of the bodies (states from dem_app)
//   applied_px, applied_py, applied_pz: impulse of all external forces since the start:
//                                       the uniform force on every node plus the bodies' net
//                                       weight W (DEM side), integrated over the steps
//   fluid_lx, fluid_ly, fluid_lz:       angular momentum of the fluid outside the bodies about
//                                       the box centre c (minimum-image lever arms)
//   bodies_lx, bodies_ly, bodies_lz:    sum_k I_k w_k + (x_k - c) x m_k v_k (minimum image)
// momenta in N s, angular momenta in N m s. With the exact feed-forward force the fluid's and
// the bodies' external forces cancel and fluid + bodies stays at its initial value to
// round-off; with the controller the change equals `applied`. The angular momentum about c is
// conserved only without external torques and only until a disturbance reaches the box's seam
// (the faces half a box from c), where streaming moves a population by a box length and so
// changes its lever arm (docs/method-loads.md section 7). tools/validate_case.py checks both.
#include <Eigen/Dense>

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
  std::vector<double> volume_;            // by shape, m^3
  std::vector<Eigen::Matrix3d> inertia_;  // by shape, per unit density, shape frame, m^5
  std::array<double, 3> weight_;
  MPI_Comm comm_;
  int rank_ = 0;
  std::ofstream out_;
};

}  // namespace lbdem
