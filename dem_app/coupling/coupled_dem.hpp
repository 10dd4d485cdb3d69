#pragma once
// dem_app's side of a coupled run: per fluid step, receive the hydrodynamic loads of the
// bodies this rank owns, advance n_DEM substeps with them held constant (plus gravity,
// buoyancy and contacts), send the new body states back (docs/method.md, "Coupling schedule").
// With --replay the loads come from a recording and the states this run computes are
// compared bit for bit with the recorded ones.
#include "coupler_lib/app/run_app.hpp"

namespace lbdem {

int run_coupled_dem(AppContext& ctx);

}  // namespace lbdem
