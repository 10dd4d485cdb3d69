#include "coupler_lib/scene/dem_section.hpp"

#include "coupler_lib/scene/scene_paths.hpp"

namespace lbdem {

const char* axis_name(int axis) {
  static constexpr const char* kNames[3] = {"x", "y", "z"};
  return kNames[axis];
}

namespace {

const MappingSchema& material_schema() {
  static const DemMaterial d;
  static const MappingSchema m{
      "dem.material",
      "contact material of bodies and walls",
      {key::number("young_modulus", "Young's modulus E of bodies and walls in Pa")
           .or_default(d.young_modulus)
           .within(Bounds::positive())
           .in("Pa"),
       key::number("poisson_ratio", "Poisson ratio nu")
           .or_default(d.poisson_ratio)
           .within({-1.0, 0.5, true, true}),
       // Hertz + Tsuji damping can only produce e in [0.114, 0.9996] or exactly 1 (no damping);
       // the restitution map rejects values outside with the admissible range.
       key::number("restitution", "normal coefficient of restitution of a binary collision")
           .or_default(d.restitution)
           .within({0.0, 1.0, true, false}),
       key::number("friction", "Coulomb friction coefficient mu")
           .or_default(d.friction)
           .within(Bounds::non_negative())}};
  return m;
}

const MappingSchema& lubrication_schema() {
  static const MappingSchema m{
      "dem.lubrication",
      "sub-grid lubrication correction",
      {key::boolean("enabled", "add the sub-grid squeeze-film correction").or_default(false),
       key::number("cutoff", "cut-off gap h_c in m (0: cutoff_cells x fluid.dx)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("m"),
       key::number("cutoff_cells", "cut-off gap h_c in lattice cells")
           .or_default(1.0)
           .within(Bounds::positive()),
       key::number("min_gap", "minimum gap h_min in m (roughness); the force saturates below it")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("m"),
       key::number("viscosity", "dynamic viscosity in Pa s (0: fluid.density x fluid.viscosity)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("Pa s")}};
  return m;
}

const MappingSchema& box_schema() {
  static const MappingSchema m{"dem.box",
                               "DEM box (default: [0, fluid.domain])",
                               {key::vec3("lo", "lower corner in m").required().in("m"),
                                key::vec3("hi", "upper corner in m").required().in("m")}};
  return m;
}

const MappingSchema& wall_schema() {
  static const MappingSchema m{
      "dem.walls[]",
      "a plane wall (LAMMPS fix wall/gran)",
      {key::choice("axis", words_of(kAxisWords), "wall normal axis").required(),
       key::choice("side", words_of(kLowerSideWords), "lo: bodies lie above the wall, hi: below")
           .required(),
       key::number("position", "wall coordinate in m (default: the box face)")
           .derived_as("the box face")
           .in("m")}};
  return m;
}

const MappingSchema& dem_output_schema() {
  static const MappingSchema m{
      "dem.output",
      "DEM-only output (HDF5 + XDMF bodies, CSV energy)",
      {key::number("interval", "simulated seconds between body snapshots (0: none)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::number("energy_interval", "simulated seconds between energy rows (0: same as interval)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::boolean("surfaces",
                    "body snapshots also carry each body's surface (<name>_surfaces.xdmf: "
                    "ParaView shows the shapes, not points)")
           .or_default(true),
       key::text("directory", "output directory (relative to the scene)").or_default(".")}};
  return m;
}

DemMaterial parse_material(Section& s) {
  DemMaterial m;
  m.young_modulus = s.get<double>("young_modulus");
  m.poisson_ratio = s.get<double>("poisson_ratio");
  m.restitution = s.get<double>("restitution");
  m.friction = s.get<double>("friction");
  s.finish();
  return m;
}

DemLubrication parse_lubrication(Section& s) {
  DemLubrication l;
  l.enabled = s.get<bool>("enabled");
  l.cutoff = s.get<double>("cutoff");
  l.cutoff_cells = s.get<double>("cutoff_cells");
  l.min_gap = s.get<double>("min_gap");
  l.viscosity = s.get<double>("viscosity");
  s.finish();  // unknown keys first: a misspelt min_gap should be named as such
  if (l.enabled && !(l.min_gap > 0))
    s.fail("min_gap", "a positive minimum gap (m) is required when lubrication is enabled");
  return l;
}

}  // namespace

const MappingSchema& dem_schema() {
  static const MappingSchema m{
      "dem",
      "discrete element bodies (LAMMPS)",
      {key::vec3("gravity", "gravitational acceleration in m/s^2")
           .or_default({0, 0, -9.81})
           .in("m/s^2"),
       key::number("buoyancy_fluid_density",
                   "fluid density in kg/m^3 for buoyancy -rho_f V g on each body in DEM-only runs "
                   "(0: none; in coupled runs the fluid side supplies it)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("kg/m^3"),
       key::number("dt", "DEM time step in s (0: dt_fraction times the Rayleigh time)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::number("dt_fraction",
                   "DEM time step as a fraction of the Rayleigh time (of the sphere dt_rule names; "
                   "paper: 0.05)")
           .or_default(0.05)
           .within({0.0, 1.0, true, false}),
       key::choice("dt_rule", words_of(kDtRuleWords),
                   "radius of the Rayleigh time for dt_fraction: clump_sphere (the smallest clump "
                   "sphere) or particle (the body's volume-equivalent sphere, the paper's rule: "
                   "larger steps, contacts resolved by fewer of them)")
           .or_default("clump_sphere"),
       key::section("material", material_schema(), "contact material of bodies and walls")
           .absent_means("all defaults"),
       key::section("box", box_schema(), "DEM box (default: [0, fluid.domain])")
           .derived_as("[0, fluid.domain]; required without a fluid section"),
       key::text("periodic", "periodic axes, any of the letters x, y, z (e.g. \"xy\")")
           .or_default(""),
       key::list("walls", wall_schema(), "plane walls (LAMMPS fix wall/gran)")
           .absent_means("no walls"),
       key::number("neighbor_skin",
                   "neighbour-list skin in m (0: half the largest clump-sphere radius)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("m"),
       key::number("max_overlap",
                   "coupled runs stop when two bodies' clump spheres overlap deeper than this "
                   "fraction of the smaller sphere radius (0: no check)")
           .or_default(0.5)
           .within(Bounds::closed(0.0, 2.0)),
       key::section("output", dem_output_schema(),
                    "DEM-only output (HDF5 + XDMF bodies, CSV energy)")
           .absent_means("all defaults"),
       key::section("lubrication", lubrication_schema(), "sub-grid lubrication correction")
           .absent_means("all defaults")}};
  return m;
}

DemParams parse_dem(Section& s) {
  DemParams p;
  p.gravity = s.vec3("gravity");
  p.buoyancy_fluid_density = s.get<double>("buoyancy_fluid_density");
  p.dt = s.get<double>("dt");
  p.dt_fraction = s.get<double>("dt_fraction");
  p.dt_rule = value_of(kDtRuleWords, s.choice("dt_rule"));
  {
    auto m = s.section_or_defaults("material");
    p.material = parse_material(m);
  }
  if (auto b = s.optional_section("box")) {
    p.has_box = true;
    p.box_lo = b->require_vec3("lo");
    p.box_hi = b->require_vec3("hi");
    for (int d = 0; d < 3; ++d)
      if (!(p.box_hi[d] > p.box_lo[d]))
        b->fail("hi",
                std::string("upper corner must exceed the lower corner along ") + axis_name(d));
    b->finish();
  }
  const auto periodic = s.get<std::string>("periodic");
  for (char c : periodic) {
    if (c != 'x' && c != 'y' && c != 'z')
      s.fail("periodic", "expected only the letters x, y and z, got '" + periodic + "'");
    p.periodic[value_of(kAxisWords, std::string(1, c))] = true;
  }
  for (auto& w : s.list("walls")) {
    DemWall wall;
    wall.axis = value_of(kAxisWords, w.require_choice("axis"));
    wall.lower = value_of(kLowerSideWords, w.require_choice("side"));
    if (w.has("position")) wall.position = w.require<double>("position");
    w.finish();
    p.walls.push_back(wall);
  }
  p.neighbor_skin = s.get<double>("neighbor_skin");
  p.max_overlap = s.get<double>("max_overlap");
  {
    auto o = s.section_or_defaults("output");
    p.output.interval = o.get<double>("interval");
    p.output.energy_interval = o.get<double>("energy_interval");
    p.output.surfaces = o.get<bool>("surfaces");
    p.output.directory = o.get<std::string>("directory");
    // Kept as written: the programs resolve it against the scene file's folder where they use it.
    check_output_directory(o, "directory", resolve_scene_path(o.file(), p.output.directory));
    o.finish();
  }
  {
    auto l = s.section_or_defaults("lubrication");
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
