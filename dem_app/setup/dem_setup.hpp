#pragma once
// Everything the DEM engine needs, resolved and checked before a single command reaches
// LAMMPS: this LAMMPS build has no exceptions, so any error there ends the process; we
// reject bad scenes here with a message naming the key instead.
#include <array>
#include <string>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/bodies_section.hpp"
#include "coupler_lib/scene/body_placement.hpp"
#include "coupler_lib/scene/dem_section.hpp"
#include "coupler_lib/scene/dem_time_step.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

struct DemSetup {
  std::string file = "scene";  // for messages
  DemParams params;
  std::array<double, 3> box_lo{}, box_hi{};  // resolved box
  std::vector<Shape> shapes;
  std::vector<BodyParams> bodies;
  // rho_f of the buoyancy -rho_f V g on every body, applied by the engine from its set-up on:
  // fluid.density in a coupled run (the lattice has no hydrostatic pressure gradient, so the
  // displaced fluid's weight is not in the penalization load; docs/method.md, "Settling
  // balance"), dem.buoyancy_fluid_density in a DEM-only run, 0 for none.
  double buoyancy_density = 0;
  // Creates LAMMPS's fix external so per-body loads (hydrodynamic force and torque, or
  // buoyancy) can be imposed; scenes without loads do not pay for it.
  bool external_loads = false;
  std::string lammps_log = "none";  // LAMMPS log file (errors are written there)
};

// The DEM part of a scene with its shapes already built. `coupled` turns on external loads.
DemSetup make_dem_setup(const Scene& scene, std::vector<Shape> shapes, bool coupled);

// Throws SceneError for: no dem section, no shapes or bodies, bad clumps, bodies outside the
// box or through a wall, overlapping bodies, walls on periodic axes, unreachable restitution.
void validate_dem_setup(const DemSetup& setup);

// DEM step of the setup's bodies (coupler_lib/scene/dem_time_step.hpp).
double dem_time_step(const DemSetup& setup);

// Largest clump-sphere radius over the shapes that bodies use, m.
double largest_sphere_radius(const DemSetup& setup);

// The neighbour skin both the contacts' and the lubrication correction's lists use:
// dem.neighbor_skin, or half the largest clump-sphere radius when it is 0, m.
double dem_neighbor_skin(const DemSetup& setup);

}  // namespace lbdem
