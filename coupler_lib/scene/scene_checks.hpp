#pragma once
// The checks of a whole scene that need more than one section: its shapes built (STL files read
// and voxelized), its bodies placed in the box, resolvable by the fluid lattice, and the memory
// the fluid lattice needs. Both programs run them at start-up on every rank, so fluid_app and
// dem_app accept and refuse exactly the same scenes with the same message, and a refusal ends
// the job cleanly before any coupling starts (coupler_lib/app/run_app.hpp).
#include <array>
#include <cstdint>
#include <optional>

#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// Bytes of memory the fluid lattice of `fluid` needs, all ranks together: two copies of the 19
// populations per cell (FluidSolver's bytes_per_cell_update) plus the porosity field (8 B) when
// the scene has bodies. A lower bound: halos, outputs and the DEM come on top.
double fluid_memory_bytes(const FluidParams& fluid, bool bodies);

// Throws SceneError for: a shape that cannot be built (unreadable or degenerate STL, a body
// thinner than the voxel spacing), a body outside the box, larger than it, through a wall or
// overlapping another body (body_placement.hpp), a body thinner than one fluid cell in a coupled
// scene, a shape's voxel_size other than fluid.dx / 2 in a scene with a fluid, and a fluid
// lattice that needs more than `memory_bytes` (the physical memory of the job's nodes; 0: not
// checked).
void check_whole_scene(const Scene& scene, double memory_bytes);

// The box the DEM works in (dem_app/setup/dem_setup.cpp resolves it alike): dem.box, else the fluid
// domain from the origin; empty without a dem section or when neither is given.
struct DemBox {
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
};
std::optional<DemBox> dem_box(const Scene& scene);

// Physical memory of this machine in bytes (sysconf).
double physical_memory_bytes();

}  // namespace lbdem
