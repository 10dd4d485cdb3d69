#pragma once
// The time schedule of a run, in one place: DEM substeps per fluid step, number of steps,
// and which steps exchange packets, write output, write checkpoints and rebalance the fluid.
//
// Substeps (paper, section "OpenLB-LAMMPS coupling"): the DEM advances n_DEM substeps of
// dt_DEM per fluid step of dt_LBM with the hydrodynamic load held constant. The paper takes
// n_DEM = dt_LBM / dt_DEM as a whole number; here n_DEM = ceil(dt_LBM / dt_DEM) and the
// substep actually used is dt_LBM / n_DEM, so it never exceeds the DEM step asked for. If
// dt_DEM >= dt_LBM the DEM uses dt_LBM (n_DEM = 1), as in the paper.
//
// The outer step is the fluid step when the scene has a fluid, else the DEM step. Outputs and
// checkpoints fall on exchange steps, so both programs are at the same time when they write.
#include <cstdint>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

struct Schedule {
  double dt = 0;                         // outer step, s (fluid step, or DEM step when DEM-only)
  double dt_dem = 0;                     // DEM substep actually used, s (0: no DEM)
  int dem_substeps = 0;                  // n_DEM per outer step (0: no DEM)
  std::int64_t steps = 0;                // outer steps to reach time.end
  int exchange_interval = 1;             // outer steps between packet exchanges
  std::int64_t output_interval = 0;      // outer steps between outputs (0: none)
  std::int64_t checkpoint_interval = 0;  // outer steps between checkpoints (0: none)
  std::int64_t rebalance_interval = 0;   // outer steps between in-run rebalancing checks (0: none)

  // `step` counts completed outer steps (1 after the first step).
  bool exchange_at(std::int64_t step) const { return step % exchange_interval == 0; }
  bool output_at(std::int64_t step) const {
    return output_interval > 0 && step % output_interval == 0;
  }
  bool checkpoint_at(std::int64_t step) const {
    return checkpoint_interval > 0 && step % checkpoint_interval == 0;
  }
  // Both programs meet here: the fluid measures its work and, above fluid.rebalance_above,
  // cuts its lattice anew and announces the new boxes; the DEM routes by them from this step's
  // states on (docs/scaling.md, "Rebalancing during a run").
  bool rebalance_at(std::int64_t step) const {
    return rebalance_interval > 0 && step % rebalance_interval == 0;
  }
};

// Outer steps to reach `end` with step `dt` (both > 0): ceil(end / dt) with a relative slack
// of 1e-9, so 0.3 / 0.1 = 2.9999999999999996 counts as 3; at least 1. Every step count of both
// programs comes from here, so they can never disagree by one step.
std::int64_t step_count(double end, double dt);

// n_DEM for a fluid step `dt_fluid` and an asked DEM step `dt_dem` (both > 0).
int dem_substeps(double dt_fluid, double dt_dem);

// `dt_fluid`: the fluid step (scene.fluid->units.dt), ignored without a fluid; `dt_dem`: the
// DEM step asked for (scene.dem->dt or the DEM's own estimate), ignored without a DEM.
// Throws SceneError when a step is missing or non-positive.
Schedule make_schedule(const Scene& scene, double dt_fluid, double dt_dem);

// The schedule of a coupled scene, identical in both programs: the fluid step and the DEM step
// of dem_time_step (coupler_lib/scene/dem_time_step.hpp) for the scene's shapes and bodies.
Schedule coupled_schedule(const Scene& scene, const std::vector<Shape>& shapes);

}  // namespace lbdem
