#pragma once
// Imposing a given force F and torque T on each rigid body exactly, through LAMMPS's
// `fix external pf/callback` and the per-atom torque array.
//
// The force is spread over the body's clump spheres with weights w_i that satisfy
// sum w_i = 1 and sum w_i (x_i - x_cm) = 0: the net force is F and the spread adds no torque,
// even when the centre of mass (from the voxelization) differs from the spheres' centroid.
// Among such weights we take the least-squares ones. The weights are invariant under the
// body's motion (the constraints are linear in the body-frame offsets), so they are computed
// once. The torque is added as T / N to each sphere's torque; the rigid fix sums them.
#include <vector>

#include "coupler_lib/geometry/shape.hpp"

namespace lbdem {

// Least-norm weights for a clump; throws std::invalid_argument when no weights can cancel
// the moment (e.g. a single sphere away from the centre of mass).
std::vector<double> force_weights(const Clump& clump);

// Per-atom columns of the LAMMPS array d2_lbdem_load (fix property/atom): what the callback
// applies to each owned sphere. LAMMPS migrates them with the atom, so a sphere that changes
// rank within a run carries its body's load along and no rank needs a table of all bodies.
inline constexpr const char* kLoadArray = "d2_lbdem_load";
inline constexpr const char* kLoadArrayName = "lbdem_load";
enum LoadColumn : int {
  kWeight = 0,       // w_i, the sphere's share of the body force
  kTorqueShare = 1,  // 1 / spheres of the body
  kForce = 2,        // 3: load + extra force of the body
  kTorque = 5,       // 3: load torque
  kKickForce = 8,    // 3: first-evaluation correction (ExternalLoads::begin_run)
  kKickTorque = 11,  // 3
  kLoadColumns = 14,
};

// What a rank applies, through the per-atom columns, to the spheres of one body in a run.
struct AppliedLoad {
  double force[3] = {0, 0, 0};  // load + extra
  double torque[3] = {0, 0, 0};
  double kick_force[3] = {0, 0, 0};
  double kick_torque[3] = {0, 0, 0};
};
void write_applied(double* columns, const AppliedLoad& load);

// Applies the per-atom columns to the local atoms in the fix external callback.
class ExternalLoads {
 public:
  // Call before every `run N pre no post no`. Velocity Verlet gives each substep's end force
  // two half-kicks (the end of that substep and the start of the next), and without a set-up
  // the run's first half-kick reuses the previous run's last force, so the body would get
  // dt_DEM / 2 (F_old - F_new) besides dt F_new. The first force evaluation of the run
  // therefore carries (F_new - F_old) / 2 extra (the kick columns), and the run delivers
  // exactly dt F_new: the momentum the fluid gave is the momentum the body gets
  // (docs/method-loads.md). With a single substep there is no such evaluation inside the run
  // and the half-kick lag remains.
  void begin_run(long substeps) { kick_ = substeps >= 2; }

  // Fills fext for the local atoms and adds the torque share to `torque` (LAMMPS arrays);
  // the first call after begin_run adds the kick columns.
  void apply(int nlocal, double* const* columns, double** fext, double** torque);

 private:
  bool kick_ = false;
};

}  // namespace lbdem
