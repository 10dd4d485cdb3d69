#include "coupler_lib/scene/fluid_output_section.hpp"

#include <algorithm>
#include <cmath>

#include "coupler_lib/scene/scene_paths.hpp"

namespace lbdem {

namespace {


const MappingSchema& slice_schema() {
  static const MappingSchema m{
      "fluid.output.fields.slices[]",
      "a plane of nodes to write",
      {key::choice("axis", words_of(kAxisWords), "normal of the plane").required(),
       key::number("position", "coordinate of the plane along its normal in m")
           .required()
           .within(Bounds::non_negative())
           .in("m")}};
  return m;
}

const MappingSchema& fields_schema() {
  static const MappingSchema m{
      "fluid.output.fields",
      "HDF5 + XDMF field files (ParaView)",
      {key::number("interval", "simulated seconds between field outputs")
           .required()
           .within(Bounds::positive())
           .in("s"),
       key::boolean("velocity", "write the velocity vector (m/s)").or_default(true),
       key::boolean("density", "write the density (kg/m^3)").or_default(false),
       key::boolean("pressure", "write the pressure relative to the rest state (Pa)")
           .or_default(false),
       key::integer("stride", "write every stride-th node along each axis")
           .or_default(1)
           .within(Bounds::at_least(1)),
       key::choice("precision", words_of(kFilePrecisionWords), "number type in the file")
           .or_default("float"),
       key::list("slices", slice_schema(),
                 "planes of nodes to write, e.g. [{axis: z, position: 0.01}]")
           .absent_means("no slices"),
       key::boolean("volume", "write the 3D volume (default: only when no slices are given)")
           .derived_as("true when no slices are given")}};
  return m;
}

const MappingSchema& series_schema() {
  static const MappingSchema m{"fluid.output.series",
                               "CSV time series of domain means",
                               {key::number("interval", "simulated seconds between rows")
                                    .required()
                                    .within(Bounds::positive())
                                    .in("s")}};
  return m;
}

FieldOutputParams parse_fields(Section& f, const UnitConverter& units,
                               const std::array<int, 3>& cells) {
  FieldOutputParams p;
  p.interval = f.require<double>("interval");
  p.every = steps_between(p.interval, units.dt);
  p.velocity = f.get<bool>("velocity");
  p.density = f.get<bool>("density");
  p.pressure = f.get<bool>("pressure");
  if (!p.velocity && !p.density && !p.pressure)
    f.fail("", "asks for no quantity: set at least one of velocity, density, pressure to true");
  p.stride = f.get<int>("stride");
  p.double_precision = value_of(kFilePrecisionWords, f.choice("precision")) == Precision::float64;
  auto slices = f.list("slices");
  p.volume = f.get<bool>("volume", slices.empty());
  for (auto& s : slices) {
    FieldSlice sl;
    sl.axis = value_of(kAxisWords, s.require_choice("axis"));
    const double extent = cells[sl.axis] * units.dx;
    // The schema bounds the plane below; the domain bounds it above.
    // The schema bounds the plane below; the domain bounds it above.
    sl.position = s.require<double>("position", Bounds::closed(0.0, extent));
    // Nodes sit at cell centres (i + 1/2) dx: take the nearest one.
    sl.index =
        std::clamp(static_cast<int>(std::floor(sl.position / units.dx)), 0, cells[sl.axis] - 1);
    sl.name = std::string("slice_") + std::string(word_of(kAxisWords, sl.axis)) + std::to_string(sl.index);
    s.finish();
    p.slices.push_back(sl);
  }
  if (!p.volume && p.slices.empty())
    f.fail("volume", "with volume: false at least one slice is needed, or nothing is written");
  f.finish();
  return p;
}

}  // namespace

const MappingSchema& stability_schema() {
  static const MappingSchema m{
      "fluid.stability",
      "divergence watch (on by default)",
      {key::integer("interval", "steps between checks for NaN, density <= 0 and Mach; 0: off")
           .or_default(100)
           .within(Bounds::non_negative()),
       key::number("max_mach", "largest admissible |u|/c_s before the run stops")
           .or_default(0.3)
           .within(Bounds{0.0, 1.7320508075688772, true, false}),
       key::text("last_good",
                 "file for the last good state, relative to the scene (default: <output "
                 "directory>/<scene name>_last_good.h5)")
           .or_default("")}};
  return m;
}

const MappingSchema& validation_schema() {
  static const MappingSchema m{
      "fluid.validation",
      "compare with an analytic solution",
      {key::choice("case", words_of(kValidationCaseWords),
                   "analytic solution the final state is compared with")
           .required(),
       key::number("tolerance",
                   "fail the run (exit 4) if the L2 relative error exceeds this; 0: only report")
           .or_default(0.0)
           .within(Bounds::non_negative())},
      {{"case",
        "taylor_green",
        {key::number("amplitude", "initial velocity amplitude of the vortex in m/s")
             .required()
             .within(Bounds::positive())
             .in("m/s"),
         key::choice("plane", words_of(kPlaneWords), "the two axes the vortices turn in")
             .or_default("xy")},
        {}}}};
  return m;
}

const MappingSchema& fluid_output_schema() {
  static const MappingSchema m{
      "fluid.output",
      "field files and time series; absent: none",
      {key::text("directory", "directory for all output files (relative to the scene)")
           .or_default("."),
       key::section("fields", fields_schema(), "HDF5 + XDMF field files (ParaView)")
           .absent_means("no field files"),
       key::section("series", series_schema(), "CSV time series of domain means")
           .absent_means("no time series")},
      {},
      {},
      {{"fields", "series"}}};
  return m;
}

namespace {

StabilityParams parse_stability(Section& s) {
  StabilityParams p;
  p.interval = s.get<long>("interval");
  p.max_mach = s.get<double>("max_mach");
  p.last_good = s.get<std::string>("last_good");
  if (!p.last_good.empty()) {
    p.last_good = resolve_scene_path(s.file(), p.last_good);
    check_output_file(s, "last_good", p.last_good);
  }
  s.finish();
  return p;
}

ValidationParams parse_validation(Section& v) {
  ValidationParams p;
  p.name = v.require_choice("case");
  p.kind = value_of(kValidationCaseWords, p.name);
  if (p.kind == ValidationCase::taylor_green) {
    p.amplitude = v.require<double>("amplitude");
    p.plane = value_of(kPlaneWords, v.choice("plane"));
  }
  p.tolerance = v.get<double>("tolerance");
  v.finish();
  return p;
}

}  // namespace

FluidOutputParams parse_fluid_output(Section& fluid, const UnitConverter& units,
                                     const std::array<int, 3>& cells) {
  FluidOutputParams p;
  // Without an output section the directory only receives a last good state, if ever.
  p.directory = resolve_scene_path(fluid.file(), ".");
  if (auto o = fluid.optional_section("output")) {
    // Like every path in a scene, relative to the scene file's folder (so a scene's output
    // lands in the same place whatever the working directory).
    p.directory = resolve_scene_path(o->file(), o->get<std::string>("directory"));
    check_output_directory(*o, "directory", p.directory);
    if (auto f = o->optional_section("fields")) p.fields = parse_fields(*f, units, cells);
    if (auto s = o->optional_section("series")) {
      SeriesOutputParams sp;
      sp.interval = s->require<double>("interval");
      sp.every = steps_between(sp.interval, units.dt);
      s->finish();
      p.series = sp;
    }
    if (!p.writes_files())
      o->fail("", "asks for nothing: add 'fields:' and/or 'series:', or remove 'output:'");
    o->finish();
  }
  {
    auto s = fluid.section_or_defaults("stability");
    p.stability = parse_stability(s);
  }
  if (auto v = fluid.optional_section("validation")) p.validation = parse_validation(*v);
  return p;
}

}  // namespace lbdem
