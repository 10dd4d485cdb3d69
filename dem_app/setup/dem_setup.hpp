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

}  // namespace lbdem
