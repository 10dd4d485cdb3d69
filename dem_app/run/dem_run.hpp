#pragma once
// DEM-only runs (`dem_app scene.yaml` with no fluid section): bodies, contacts, walls,
// gravity (and buoyancy if asked) advanced to time.end with snapshots and energies at the
// scene's output cadence.
#include <string>

#include "coupler_lib/app/run_app.hpp"
#include "dem_app/engine/lammps_engine.hpp"

namespace lbdem {

// One paragraph for logs and --check: time step, Rayleigh time, restitution map, sizes.
std::string describe_engine_inputs(const DemSetup& setup);

int run_dem_only(AppContext& ctx);

}  // namespace lbdem
