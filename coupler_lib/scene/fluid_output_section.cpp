#include "coupler_lib/scene/fluid_output_section.hpp"

#include <algorithm>
#include <cmath>

#include "coupler_lib/scene/scene_paths.hpp"

namespace lbdem {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

int axis_index(const std::string& a) {
  return a == "x" ? 0 : a == "y" ? 1 : 2;
}

// Steps between two events `interval` seconds apart; at least one step.
long steps_for(double interval, const UnitConverter& units) {
  return std::max(1L, std::lround(interval / units.dt));
}

FieldOutputParams parse_fields(Section& f, const UnitConverter& units,
                               const std::array<int, 3>& cells) {
  FieldOutputParams p;
  p.interval =
      f.require<double>("interval", "simulated seconds between field outputs", Bounds::positive());
  p.every = steps_for(p.interval, units);
  p.velocity = f.get<bool>("velocity", true, "write the velocity vector (m/s)");
  p.density = f.get<bool>("density", false, "write the density (kg/m^3)");
  p.pressure = f.get<bool>("pressure", false, "write the pressure relative to the rest state (Pa)");
  if (!p.velocity && !p.density && !p.pressure)
    f.fail("", "asks for no quantity: set at least one of velocity, density, pressure to true");
  p.stride =
      f.get<int>("stride", 1, "write every stride-th node along each axis", Bounds::at_least(1));
  p.double_precision =
      f.choice("precision", "float", {"float", "double"}, "number type in the file") == "double";
  auto slices = f.list("slices", "planes of nodes to write, e.g. [{axis: z, position: 0.01}]");
  p.volume = f.get<bool>("volume", slices.empty(),
                         "write the 3D volume (default: only when no slices are given)");
  for (auto& s : slices) {
    FieldSlice sl;
    sl.axis = axis_index(s.require_choice("axis", {"x", "y", "z"}, "normal of the plane"));
    const double extent = cells[sl.axis] * units.dx;
    sl.position = s.require<double>("position", "coordinate of the plane along its normal in m",
                                    Bounds::closed(0.0, extent));
    // Nodes sit at cell centres (i + 1/2) dx: take the nearest one.
    sl.index =
        std::clamp(static_cast<int>(std::floor(sl.position / units.dx)), 0, cells[sl.axis] - 1);
    sl.name = std::string("slice_") + kAxisNames[sl.axis] + std::to_string(sl.index);
    s.finish();
    p.slices.push_back(sl);
  }
  if (!p.volume && p.slices.empty())
    f.fail("volume", "with volume: false at least one slice is needed, or nothing is written");
  f.finish();
  return p;
}

StabilityParams parse_stability(Section& s) {
  StabilityParams p;
  p.interval =
      s.get<long>("interval", 100L, "steps between checks for NaN, density <= 0 and Mach; 0: off",
                  Bounds::non_negative());
  p.max_mach = s.get<double>("max_mach", 0.3, "largest admissible |u|/c_s before the run stops",
                             Bounds{0.0, 1.7320508075688772, true, false});
  p.last_good = s.get<std::string>(
      "last_good", "",
      "file for the last good state, relative to the scene (default: <output directory>/<scene "
      "name>_last_good.h5)");
  if (!p.last_good.empty()) {
    p.last_good = resolve_scene_path(s.file(), p.last_good);
    check_output_file(s, "last_good", p.last_good);
  }
  s.finish();
  return p;
}

ValidationParams parse_validation(Section& v) {
  ValidationParams p;
  p.name = v.require_choice("case", {"poiseuille", "couette", "taylor_green"},
                            "analytic solution the final state is compared with");
  p.kind = p.name == "poiseuille" ? ValidationCase::poiseuille
           : p.name == "couette"  ? ValidationCase::couette
                                  : ValidationCase::taylor_green;
  if (p.kind == ValidationCase::taylor_green) {
    p.amplitude = v.require<double>("amplitude", "initial velocity amplitude of the vortex in m/s",
                                    Bounds::positive());
    const std::string plane =
        v.choice("plane", "xy", {"xy", "yz", "zx"}, "the two axes the vortices turn in");
    p.plane = plane == "xy"   ? std::array<int, 2>{0, 1}
              : plane == "yz" ? std::array<int, 2>{1, 2}
                              : std::array<int, 2>{2, 0};
  }
  p.tolerance = v.get<double>("tolerance", 0.0,
                              "fail the run (exit 4) if the L2 relative error exceeds this; 0: "
                              "only report",
                              Bounds::non_negative());
  v.finish();
  return p;
}

}  // namespace

FluidOutputParams parse_fluid_output(Section& fluid, const UnitConverter& units,
                                     const std::array<int, 3>& cells) {
  FluidOutputParams p;
  // Without an output section the directory only receives a last good state, if ever.
  p.directory = resolve_scene_path(fluid.file(), ".");
  if (auto o = fluid.optional_section("output", "field files and time series; absent: none")) {
    // Like every path in a scene, relative to the scene file's folder (so a scene's output
    // lands in the same place whatever the working directory).
    p.directory = resolve_scene_path(
        o->file(), o->get<std::string>("directory", ".",
                                       "directory for all output files (relative to the scene)"));
    check_output_directory(*o, "directory", p.directory);
    if (auto f = o->optional_section("fields", "HDF5 + XDMF field files (ParaView)"))
      p.fields = parse_fields(*f, units, cells);
    if (auto s = o->optional_section("series", "CSV time series of domain means")) {
      SeriesOutputParams sp;
      sp.interval =
          s->require<double>("interval", "simulated seconds between rows", Bounds::positive());
      sp.every = steps_for(sp.interval, units);
      s->finish();
      p.series = sp;
    }
    if (!p.writes_files())
      o->fail("", "asks for nothing: add 'fields:' and/or 'series:', or remove 'output:'");
    o->finish();
  }
  {
    auto s = fluid.section_or_defaults("stability", "divergence watch (on by default)");
    p.stability = parse_stability(s);
  }
  if (auto v = fluid.optional_section("validation", "compare with an analytic solution"))
    p.validation = parse_validation(*v);
  return p;
}

}  // namespace lbdem
