#pragma once
// The `dem:` section of a scene: contact material, box and walls, gravity and buoyancy, the
// DEM time step and the DEM-only output. Defaults are the hindered-settling parameters of the
// paper (table "Summary of physical and numerical parameters used for hindered settling").
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/scene/fluid_section.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

// Contact material shared by body-body and body-wall contacts.
struct DemMaterial {
  double young_modulus = 5e4;  // Pa
  double poisson_ratio = 0.3;
  double restitution = 0.9;  // normal coefficient of restitution of a binary collision
  double friction = 0.6;     // Coulomb coefficient of the Mindlin tangential force
};

// A plane wall normal to `axis` (0, 1, 2); `lower` walls keep bodies above `position`.
struct DemWall {
  int axis = 2;
  bool lower = true;
  std::optional<double> position;  // m; empty: the box face
};

struct DemOutput {
  double interval = 0;         // s of simulated time between body snapshots; 0 = none
  double energy_interval = 0;  // s between CSV energy rows; 0 = same as `interval`
  bool surfaces = true;        // snapshots carry the body surfaces (body_output.hpp)
  std::string directory = ".";
};

// Lubrication correction below the grid scale (docs/lubrication.md): the squeeze-film force
// between clump spheres of different bodies, and between a clump sphere and a plane wall, minus
// its value at the cut-off gap, saturated at the minimum gap.
struct DemLubrication {
  bool enabled = false;
  double cutoff = 0;          // m, h_c; 0: cutoff_cells x fluid.dx
  double cutoff_cells = 1.0;  // h_c in lattice cells when cutoff is 0
  double min_gap = 0;         // m, h_min (surface roughness); required when enabled
  double viscosity = 0;       // Pa s, dynamic; 0: fluid.density x fluid.viscosity
};

struct DemParams {
  std::array<double, 3> gravity{0, 0, -9.81};  // m/s^2
  double buoyancy_fluid_density = 0;           // kg/m^3; DEM-only runs: -rho_f V g per body
  double dt = 0;                               // s; 0 = dt_fraction * Rayleigh time
  double dt_fraction = 0.05;                   // of the Rayleigh time (paper: 0.05 t_c)
  // Whose Rayleigh time: "clump_sphere" (the smallest clump sphere) or "particle" (the
  // volume-equivalent sphere of the body, the paper's rule).
  DtRule dt_rule = DtRule::clump_sphere;
  DemMaterial material;
  bool has_box = false;  // false: the box is [0, fluid.domain]
  std::array<double, 3> box_lo{0, 0, 0};
  std::array<double, 3> box_hi{0, 0, 0};
  std::array<bool, 3> periodic{false, false, false};
  std::vector<DemWall> walls;
  double neighbor_skin = 0;  // m; 0 = half the largest clump-sphere radius
  double max_overlap = 0.5;  // coupled stability watch: deepest overlap / smaller sphere radius
  DemOutput output;
  DemLubrication lubrication;
};

const MappingSchema& dem_schema();
DemParams parse_dem(Section& s);

// Resolves dem.lubrication's cutoff and viscosity from the fluid section (both programs call it
// through parse_scene, so both refuse the same scenes); throws SceneError naming the key.
void resolve_lubrication(DemLubrication& l, const FluidParams* fluid, const std::string& file);

// "x", "y" or "z" for an axis index.
const char* axis_name(int axis);

}  // namespace lbdem
