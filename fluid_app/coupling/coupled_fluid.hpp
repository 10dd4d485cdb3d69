#pragma once
// fluid_app's side of a coupled run (paper, "OpenLB-LAMMPS coupling"; design.md, one
// coupling step):
//   1. collide + stream with HLBM forcing from the current body states;
//   2. momentum exchange -> partial force/torque per body on this rank;
//   3. partial loads to the DEM rank that owns each body (the coupler sums them there);
//   4. (DEM: n_DEM substeps with the load held)
//   5. new body states from the DEM, every body that can touch this rank;
//   6. porosity and body table updated for the moved surfaces.
// With --replay the states come from a recording instead of dem_app, and the loads this
// run computes are compared bit for bit with the recorded ones.
#include "coupler_lib/app/run_app.hpp"

namespace lbdem {

int run_coupled_fluid(AppContext& ctx);

}  // namespace lbdem
