#pragma once
// From a DemSetup to the lubrication correction's tables, and the check that the explicit DEM
// step can integrate it (docs/lubrication.md).
#include "dem_app/lubrication/lubrication.hpp"
#include "dem_app/setup/dem_setup.hpp"

namespace lbdem {

// Per-atom body and radius tables (atoms as the engine writes them: body after body, clump
// spheres in order, then the helper spheres of one-sphere bodies, which take no part) and the
// walls. `shapes` are the scene's clumps before helper spheres are added. Disabled (a default
// Lubrication) when dem.lubrication.enabled is false.
Lubrication make_lubrication(const DemSetup& setup, const std::vector<Shape>& shapes,
                             const std::vector<Shape>& lammps_shapes);

// The correction is a damper of rate c/m on each body; the velocity-Verlet step stays stable
// for dt c/m below 2. The largest c is that of every clump sphere of a body at the minimum gap
// from a wall at once (an upper bound). Throws SceneError naming dem.lubrication.min_gap when
// dt c/m exceeds 1 for some body.
void check_lubrication_step(const DemSetup& setup, double dt);

}  // namespace lbdem
