#include "coupler_lib/scene/fluid_section.hpp"

#include <algorithm>
#include <cmath>

#include "coupler_lib/scene/band_calibration.hpp"

namespace lbdem {

namespace {

constexpr const char* kFaceNames[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

// A face written as a mapping: its type, and the velocity or pressure that type needs.
const MappingSchema& face_schema() {
  static const MappingSchema m{
      "fluid.boundaries.<face>",
      "one face of the box written as a mapping, e.g. {type: moving_wall, velocity: [u, v, w]}",
      {key::choice("type", words_of(kFaceTypeWords), "boundary type").required()},
      {{"type",
        "moving_wall",
        {key::vec3("velocity", "wall velocity in m/s (tangential)").required().in("m/s")},
        {}},
       {"type",
        "pressure",
        {key::number("pressure", "pressure in Pa relative to the reference")
             .or_default(0.0)
             .in("Pa")},
        {}}}};
  return m;
}

// A face as a word; a moving wall needs its velocity, so it is written as a mapping.
const MappingSchema& boundaries_schema() {
  static const MappingSchema m = [] {
    MappingSchema b{"fluid.boundaries", "per-face boundary conditions", {}};
    for (const char* face : kFaceNames) {
      KeySchema k = key::choice(face, {"periodic", "wall", "pressure"},
                                std::string("boundary of the ") + face + " face")
                        .or_default("periodic");
      k.mapping = &face_schema();
      b.keys.push_back(k);
    }
    return b;
  }();
  return m;
}

const MappingSchema& resolution_schema() {
  static const MappingSchema m{
      "fluid.resolution",
      "reference length resolved by a number of cells",
      {key::number("length", "reference length in m").required().within(Bounds::positive()).in("m"),
       key::integer("cells", "cells across the reference length")
           .required()
           .within(Bounds::at_least(1))}};
  return m;
}

const MappingSchema& control_schema() {
  static const MappingSchema m{
      "fluid.mean_velocity_control",
      "uniform force that holds the mean fluid velocity",
      {key::vec3("target", "mean fluid velocity to hold, m/s").or_default({0, 0, 0}).in("m/s"),
       key::number("gain", "proportional gain per update")
           .or_default(0.5)
           .within(Bounds::closed(0.0, 1.0)),
       key::number("integral_gain", "integral gain per update")
           .or_default(0.05)
           .within(Bounds::closed(0.0, 0.5)),
       key::number("interval", "seconds between controller updates (0: every step)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::boolean("feed_forward",
                    "start from the exact force that balances the bodies' net weight")
           .or_default(true)}};
  return m;
}

FaceBoundary parse_face(Section& b, int face) {
  const std::string key = kFaceNames[face];
  FaceBoundary fb;
  if (b.has(key) && b.node()[key].IsScalar() && b.node()[key].Scalar() == "moving_wall")
    b.fail(key, "a moving wall needs its velocity: write {type: moving_wall, velocity: [u, v, w]}");
  if (b.has(key) && b.node()[key].IsMap()) {
    Section s = b.section(key);
    fb.type = value_of(kFaceTypeWords, s.require_choice("type"));
    if (fb.type == FaceType::moving_wall) {
      fb.velocity = s.require_vec3("velocity");
      if (fb.velocity[face / 2] != 0.0)
        s.fail("velocity", "a moving wall slides along its plane: the component along axis " +
                               std::to_string(face / 2) + " (the face normal) must be 0");
    }
    if (fb.type == FaceType::pressure) fb.pressure = s.get<double>("pressure");
    s.finish();
  } else {
    fb.type = value_of(kFaceTypeWords, b.choice(key));
  }
  return fb;
}

}  // namespace

const char* face_name(int face) {
  return kFaceNames[face];
}

const char* face_type_name(FaceType t) {
  return word_of(kFaceTypeWords, t).data();  // the words are literals: null-terminated
}

const MappingSchema& fluid_schema() {
  static const MappingSchema m{
      "fluid",
      "lattice Boltzmann fluid",
      {key::vec3("domain", "box size [Lx, Ly, Lz] in m")
           .required()
           .within(Bounds::positive())
           .in("m"),
       key::number("dx", "lattice spacing in m")
           .absent_means("give resolution instead")
           .within(Bounds::positive())
           .in("m"),
       key::section("resolution", resolution_schema(),
                    "reference length resolved by a number of cells: dx = length / cells")
           .absent_means("give dx instead"),
       key::number("density", "fluid density in kg/m^3")
           .or_default(1000.0)
           .within(Bounds::positive())
           .in("kg/m^3"),
       key::number("viscosity", "kinematic viscosity in m^2/s")
           .required()
           .within(Bounds::positive())
           .in("m^2/s"),
       key::number("tau", "BGK relaxation time").or_default(0.6).within(Bounds::above(0.5)),
       key::choice("precision", words_of(kPrecisionWords), "floating-point type")
           .or_default("double"),
       key::choice("porosity_lookup", words_of(kPorosityLookupWords),
                   "how a node reads a body's smoothed reference porosity: nearest (the paper's "
                   "nearest voxel; narrower band, d in steps of 1/19, closer settling speeds: "
                   "docs/validation.md) or trilinear (d continuous in the pose; wider band: "
                   "docs/performance.md)")
           .or_default("nearest"),
       key::choice("hydrodynamic_radius", words_of(kHydrodynamicRadiusWords),
                   "calibrated: the fluid sees each body's surface moved inward by the band's "
                   "measured hydrodynamic-radius excess at this tau and lookup (docs/method.md), "
                   "nominal: the true surface (the paper's construction)")
           .or_default("calibrated"),
       key::number("characteristic_velocity",
                   "expected flow speed in m/s (logs Mach and Re; 0 = not given)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("m/s"),
       key::number("characteristic_length",
                   "length in m for the Reynolds number (default: smallest domain edge)")
           .derived_as("the smallest edge of domain")
           .within(Bounds::positive())
           .in("m"),
       key::vec3("body_force", "uniform acceleration of the fluid in m/s^2")
           .or_default({0, 0, 0})
           .in("m/s^2"),
       key::section("mean_velocity_control", control_schema(),
                    "uniform force that holds the mean fluid velocity")
           .absent_means("no control"),
       key::choice("loads", words_of(kLoadMethodWords),
                   "hydrodynamic load on bodies: from the penalization (conserves momentum) or by "
                   "momentum exchange")
           .or_default("penalization"),
       key::choice("decomposition", words_of(kDecompositionWords),
                   "how the lattice is split over the fluid ranks: regular (equal blocks) or "
                   "balanced (the cuts of each axis placed so that every rank gets the same work "
                   "of the initial bodies; docs/scaling.md)")
           .or_default("regular"),
       key::number("covered_cell_weight",
                   "work of a lattice cell a body covers (band and interior: porosity, "
                   "penalization, load sums) in plain fluid cells, for decomposition: balanced "
                   "(measured: docs/scaling.md)")
           .or_default(10.0)
           .within(Bounds::at_least(1.0)),
       key::number("rebalance_above",
                   "for decomposition: balanced, at a restart or an in-run check "
                   "(rebalance_interval): the load imbalance (max / mean of the weighted work) "
                   "measured there above which the lattice is cut anew by the measured work; at "
                   "or below it the cuts are kept (docs/scaling.md)")
           .or_default(1.1)
           .within(Bounds::at_least(1.0)),
       key::number("rebalance_interval",
                   "for decomposition: balanced in a coupled run: simulated s between checks of "
                   "the measured load imbalance, each cutting the lattice anew while the run goes "
                   "on when it is above rebalance_above (docs/scaling.md)")
           .or_default(0.0)
           .within(Bounds::non_negative())
           .in("s"),
       key::section("boundaries", boundaries_schema(), "per-face boundary conditions")
           .absent_means("triply periodic"),
       key::section("output", fluid_output_schema(), "field files and time series; absent: none")
           .absent_means("no output files"),
       key::section("stability", stability_schema(), "divergence watch (on by default)")
           .absent_means("all defaults"),
       key::section("validation", validation_schema(), "compare with an analytic solution")
           .absent_means("no comparison")},
      {},
      {{"dx", "resolution"}}};
  return m;
}

FluidParams parse_fluid(Section& s) {
  FluidParams p;
  p.domain = s.require_vec3("domain");
  if (s.has("dx") == s.has("resolution"))
    s.fail("",
           "give the lattice spacing either as 'dx' (m) or as 'resolution: {length: L, "
           "cells: N}' (a reference length L in m resolved by N cells), exactly one of them");
  if (s.has("dx")) {
    p.dx = s.require<double>("dx");
  } else {
    Section r = s.section("resolution");
    const double length = r.require<double>("length");
    const int n = r.require<int>("cells");
    r.finish();
    p.dx = length / n;
  }
  p.density = s.get<double>("density");
  p.viscosity = s.require<double>("viscosity");
  p.tau = s.get<double>("tau");
  p.precision = value_of(kPrecisionWords, s.choice("precision"));
  p.porosity_lookup = value_of(kPorosityLookupWords, s.choice("porosity_lookup"));
  p.hydrodynamic_radius = value_of(kHydrodynamicRadiusWords, s.choice("hydrodynamic_radius"));
  for (int d = 0; d < 3; ++d) {
    const double n = p.domain[d] / p.dx;
    p.cells[d] = static_cast<int>(std::lround(n));
    if (p.cells[d] < 1 || std::abs(n - p.cells[d]) > 1e-6 * n)
      s.fail("domain", "domain size must be a whole number of cells of dx; got " +
                           std::to_string(n) + " cells along axis " + std::to_string(d));
  }
  p.characteristic_velocity = s.get<double>("characteristic_velocity");
  p.characteristic_length =
      s.get<double>("characteristic_length", *std::min_element(p.domain.begin(), p.domain.end()));
  p.body_force = s.vec3("body_force");
  if (auto c = s.optional_section("mean_velocity_control")) {
    p.control.enabled = true;
    p.control.target = c->vec3("target");
    p.control.gain = c->get<double>("gain");
    p.control.integral_gain = c->get<double>("integral_gain");
    p.control.interval = c->get<double>("interval");
    p.control.feed_forward = c->get<bool>("feed_forward");
    c->finish();
  }
  p.loads = value_of(kLoadMethodWords, s.choice("loads"));
  p.decomposition = value_of(kDecompositionWords, s.choice("decomposition"));
  p.covered_cell_weight = s.get<double>("covered_cell_weight");
  p.rebalance_above = s.get<double>("rebalance_above");
  p.rebalance_interval = s.get<double>("rebalance_interval");
  if (p.rebalance_interval > 0 && p.decomposition != DecompositionKind::balanced)
    s.fail("rebalance_interval",
           "rebalancing during the run needs decomposition: balanced (the regular blocks are "
           "never cut anew); remove rebalance_interval or set decomposition: balanced");
  {
    auto b = s.section_or_defaults("boundaries");
    for (int f = 0; f < 6; ++f) p.faces[f] = parse_face(b, f);
    for (int a = 0; a < 3; ++a) {
      const bool lo = p.faces[2 * a].type == FaceType::periodic;
      const bool hi = p.faces[2 * a + 1].type == FaceType::periodic;
      if (lo != hi)
        b.fail(kFaceNames[2 * a + (lo ? 1 : 0)],
               std::string("periodic faces come in pairs: ") + kFaceNames[2 * a] + " and " +
                   kFaceNames[2 * a + 1] + " must both be periodic or both not");
    }
    b.finish();
  }
  p.units = UnitConverter::from_tau(p.dx, p.tau, p.viscosity, p.density);
  p.units.char_velocity = p.characteristic_velocity;
  p.units.char_length = p.characteristic_length;
  if (p.control.interval > 0) p.control.every = steps_between(p.control.interval, p.units.dt);
  const UnitConverter& u = p.units;
  if (p.tau < UnitLimits{}.min_tau) s.fail("tau", u.check());
  if (p.hydrodynamic_radius == HydrodynamicRadius::calibrated &&
      !band_radius_excess_cells(p.tau, p.porosity_lookup))
    s.fail("hydrodynamic_radius",
           "the band's radius excess is calibrated for tau in " + band_calibration_range() +
               " with the " + std::string(word_of(kPorosityLookupWords, p.porosity_lookup)) +
               " lookup; tau is " + std::to_string(p.tau) +
               ": set hydrodynamic_radius: nominal, or measure it (tools/calibrate_band.py)");
  if (const std::string m = u.check(); !m.empty()) s.fail("characteristic_velocity", m);
  p.output = parse_fluid_output(s, p.units, p.cells);
  s.finish();
  return p;
}

}  // namespace lbdem
