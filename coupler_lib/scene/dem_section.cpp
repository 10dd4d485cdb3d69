#include "coupler_lib/scene/dem_section.hpp"

#include "coupler_lib/scene/scene_paths.hpp"

namespace lbdem {

const char* axis_name(int axis) {
  static constexpr const char* kNames[3] = {"x", "y", "z"};
  return kNames[axis];
}

namespace {

int axis_index(const std::string& a) {
  return a == "x" ? 0 : a == "y" ? 1 : 2;
}

DemMaterial parse_material(Section& s) {
  DemMaterial m;
  m.young_modulus =
      s.get<double>("young_modulus", m.young_modulus, "Young's modulus E of bodies and walls in Pa",
                    Bounds::positive());
  m.poisson_ratio =
      s.get<double>("poisson_ratio", m.poisson_ratio, "Poisson ratio nu", {-1.0, 0.5, true, true});
  // Hertz + Tsuji damping can only produce e in [0.114, 0.9996] or exactly 1 (no damping);
  // the restitution map rejects values outside with the admissible range.
  m.restitution = s.get<double>("restitution", m.restitution,
                                "normal coefficient of restitution of a binary collision",
                                {0.0, 1.0, true, false});
  m.friction = s.get<double>("friction", m.friction, "Coulomb friction coefficient mu",
                             Bounds::non_negative());
  s.finish();
  return m;
}

DemLubrication parse_lubrication(Section& s) {
  DemLubrication l;
  l.enabled = s.get<bool>("enabled", false, "add the sub-grid squeeze-film correction");
  l.cutoff = s.get<double>("cutoff", 0.0, "cut-off gap h_c in m (0: cutoff_cells x fluid.dx)",
                           Bounds::non_negative());
  l.cutoff_cells =
      s.get<double>("cutoff_cells", 1.0, "cut-off gap h_c in lattice cells", Bounds::positive());
  l.min_gap = s.get<double>("min_gap", 0.0,
                            "minimum gap h_min in m (roughness); the force saturates below it",
                            Bounds::non_negative());
  l.viscosity = s.get<double>("viscosity", 0.0,
                              "dynamic viscosity in Pa s (0: fluid.density x fluid.viscosity)",
                              Bounds::non_negative());
  s.finish();  // unknown keys first: a misspelt min_gap should be named as such
  if (l.enabled && !(l.min_gap > 0))
    s.fail("min_gap", "a positive minimum gap (m) is required when lubrication is enabled");
  return l;
}

}  // namespace

DemParams parse_dem(Section& s) {
  DemParams p;
  p.gravity = s.vec3("gravity", {0, 0, -9.81}, "gravitational acceleration in m/s^2");
  p.buoyancy_fluid_density = s.get<double>(
      "buoyancy_fluid_density", 0.0,
      "fluid density in kg/m^3 for buoyancy -rho_f V g on each body in DEM-only runs (0: none; "
      "in coupled runs the fluid side supplies it)",
      Bounds::non_negative());
  p.dt = s.get<double>("dt", 0.0, "DEM time step in s (0: dt_fraction times the Rayleigh time)",
                       Bounds::non_negative());
  p.dt_fraction = s.get<double>("dt_fraction", 0.05,
                                "DEM time step as a fraction of the Rayleigh time (of the sphere "
                                "dt_rule names; paper: 0.05)",
                                {0.0, 1.0, true, false});
  p.dt_rule = s.choice("dt_rule", "clump_sphere", {"clump_sphere", "particle"},
                       "radius of the Rayleigh time for dt_fraction: clump_sphere (the smallest "
                       "clump sphere) or particle (the body's volume-equivalent sphere, the "
                       "paper's rule: larger steps, contacts resolved by fewer of them)");
  {
    auto m = s.section_or_defaults("material", "contact material of bodies and walls");
    p.material = parse_material(m);
  }
  if (auto b = s.optional_section("box", "DEM box (default: [0, fluid.domain])")) {
    p.has_box = true;
    p.box_lo = b->require_vec3("lo", "lower corner in m");
    p.box_hi = b->require_vec3("hi", "upper corner in m");
    for (int d = 0; d < 3; ++d)
      if (!(p.box_hi[d] > p.box_lo[d]))
        b->fail("hi",
                std::string("upper corner must exceed the lower corner along ") + axis_name(d));
    b->finish();
  }
  const auto periodic =
      s.get<std::string>("periodic", "", "periodic axes, any of the letters x, y, z (e.g. \"xy\")");
  for (char c : periodic) {
    if (c != 'x' && c != 'y' && c != 'z')
      s.fail("periodic", "expected only the letters x, y and z, got '" + periodic + "'");
    p.periodic[axis_index(std::string(1, c))] = true;
  }
  for (auto& w : s.list("walls", "plane walls (LAMMPS fix wall/gran)")) {
    DemWall wall;
    wall.axis = axis_index(w.require_choice("axis", {"x", "y", "z"}, "wall normal axis"));
    wall.lower =
        w.require_choice("side", {"lo", "hi"}, "lo: bodies lie above the wall, hi: below") == "lo";
    if (w.has("position"))
      wall.position = w.require<double>("position", "wall coordinate in m (default: the box face)");
    w.finish();
    p.walls.push_back(wall);
  }
  p.neighbor_skin = s.get<double>(
      "neighbor_skin", 0.0, "neighbour-list skin in m (0: half the largest clump-sphere radius)",
      Bounds::non_negative());
  p.max_overlap = s.get<double>(
      "max_overlap", 0.5,
      "coupled runs stop when two bodies' clump spheres overlap deeper than this fraction of the "
      "smaller sphere radius (0: no check)",
      Bounds::closed(0.0, 2.0));
  {
    auto o = s.section_or_defaults("output", "DEM-only output (HDF5 + XDMF bodies, CSV energy)");
    p.output.interval =
        o.get<double>("interval", 0.0, "simulated seconds between body snapshots (0: none)",
                      Bounds::non_negative());
    p.output.energy_interval = o.get<double>(
        "energy_interval", 0.0, "simulated seconds between energy rows (0: same as interval)",
        Bounds::non_negative());
    p.output.surfaces = o.get<bool>(
        "surfaces", true,
        "body snapshots also carry each body's surface (<name>_surfaces.xdmf: ParaView shows the "
        "shapes, not points)");
    p.output.directory =
        o.get<std::string>("directory", ".", "output directory (relative to the scene)");
    // Kept as written: the programs resolve it against the scene file's folder where they use it.
    check_output_directory(o, "directory", resolve_scene_path(o.file(), p.output.directory));
    o.finish();
  }
  {
    auto l = s.section_or_defaults("lubrication", "sub-grid lubrication correction");
    p.lubrication = parse_lubrication(l);
  }
  s.finish();
  return p;
}

void resolve_lubrication(DemLubrication& l, const FluidParams* fluid, const std::string& file) {
  if (!l.enabled) return;
  const std::string where = file + ": dem.lubrication.";
  if (l.viscosity == 0) {
    if (!fluid)
      throw SceneError(where + "viscosity: required (Pa s) when the scene has no fluid section");
    l.viscosity = fluid->density * fluid->viscosity;
  }
  if (l.cutoff == 0) {
    if (!fluid)
      throw SceneError(where + "cutoff: required (m) when the scene has no fluid section");
    l.cutoff = l.cutoff_cells * fluid->dx;
  }
  if (!(l.min_gap < l.cutoff))
    throw SceneError(where + "min_gap: must be below the cut-off gap " + std::to_string(l.cutoff) +
                     " m");
}

}  // namespace lbdem
