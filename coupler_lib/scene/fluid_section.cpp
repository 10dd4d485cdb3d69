#include "coupler_lib/scene/fluid_section.hpp"

#include <algorithm>
#include <cmath>

#include "coupler_lib/scene/band_calibration.hpp"

namespace lbdem {

namespace {

constexpr const char* kFaceNames[6] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};

FaceType face_type_from(const std::string& w) {
  if (w == "wall") return FaceType::wall;
  if (w == "moving_wall") return FaceType::moving_wall;
  if (w == "pressure") return FaceType::pressure;
  return FaceType::periodic;
}

const std::vector<std::string> kFaceTypes = {"periodic", "wall", "moving_wall", "pressure"};

FaceBoundary parse_face(Section& b, int face) {
  const std::string key = kFaceNames[face];
  FaceBoundary fb;
  const std::string doc = "boundary of the " + key + " face";
  if (b.has(key) && b.node()[key].IsMap()) {
    Section s = b.section(key, doc);
    fb.type = face_type_from(s.require_choice("type", kFaceTypes, "boundary type"));
    if (fb.type == FaceType::moving_wall) {
      fb.velocity = s.require_vec3("velocity", "wall velocity in m/s (tangential)");
      if (fb.velocity[face / 2] != 0.0)
        s.fail("velocity", "a moving wall slides along its plane: the component along axis " +
                               std::to_string(face / 2) + " (the face normal) must be 0");
    }
    if (fb.type == FaceType::pressure)
      fb.pressure = s.get<double>("pressure", 0.0, "pressure in Pa relative to the reference");
    s.finish();
  } else {
    fb.type = face_type_from(b.choice(key, "periodic", kFaceTypes, doc));
    if (fb.type == FaceType::moving_wall)
      b.fail(key,
             "a moving wall needs its velocity: write {type: moving_wall, velocity: [u, v, w]}");
  }
  return fb;
}

}  // namespace

const char* face_name(int face) {
  return kFaceNames[face];
}

const char* face_type_name(FaceType t) {
  switch (t) {
    case FaceType::periodic:
      return "periodic";
    case FaceType::wall:
      return "wall";
    case FaceType::moving_wall:
      return "moving_wall";
    case FaceType::pressure:
      return "pressure";
  }
  return "?";
}

FluidParams parse_fluid(Section& s) {
  FluidParams p;
  p.domain = s.require_vec3("domain", "box size [Lx, Ly, Lz] in m", Bounds::positive());
  if (s.has("dx") == s.has("resolution"))
    s.fail("",
           "give the lattice spacing either as 'dx' (m) or as 'resolution: {length: L, "
           "cells: N}' (a reference length L in m resolved by N cells), exactly one of them");
  if (s.has("dx")) {
    p.dx = s.require<double>("dx", "lattice spacing in m", Bounds::positive());
  } else {
    Section r = s.section("resolution", "reference length resolved by a number of cells");
    const double length = r.require<double>("length", "reference length in m", Bounds::positive());
    const int n = r.require<int>("cells", "cells across the reference length", Bounds::at_least(1));
    r.finish();
    p.dx = length / n;
  }
  p.density = s.get<double>("density", 1000.0, "fluid density in kg/m^3", Bounds::positive());
  p.viscosity = s.require<double>("viscosity", "kinematic viscosity in m^2/s", Bounds::positive());
  p.tau = s.get<double>("tau", 0.6, "BGK relaxation time", Bounds::above(0.5));
  p.precision = s.choice("precision", "double", {"double", "float"}, "floating-point type");
  p.porosity_lookup = s.choice(
      "porosity_lookup", "nearest", {"nearest", "trilinear"},
      "how a node reads a body's smoothed reference porosity: nearest (the paper's nearest "
      "voxel; narrower band, d in steps of 1/19, closer settling speeds: docs/validation.md) "
      "or trilinear (d continuous in the pose; wider band: docs/performance.md)");
  p.hydrodynamic_radius = s.choice(
      "hydrodynamic_radius", "calibrated", {"calibrated", "nominal"},
      "calibrated: the fluid sees each body's surface moved inward by the band's measured "
      "hydrodynamic-radius excess at this tau and lookup (docs/method.md), nominal: the true "
      "surface (the paper's construction)");
  for (int d = 0; d < 3; ++d) {
    const double n = p.domain[d] / p.dx;
    p.cells[d] = static_cast<int>(std::lround(n));
    if (p.cells[d] < 1 || std::abs(n - p.cells[d]) > 1e-6 * n)
      s.fail("domain", "domain size must be a whole number of cells of dx; got " +
                           std::to_string(n) + " cells along axis " + std::to_string(d));
  }
  p.characteristic_velocity = s.get<double>(
      "characteristic_velocity", 0.0,
      "expected flow speed in m/s (logs Mach and Re; 0 = not given)", Bounds::non_negative());
  p.characteristic_length = s.get<double>(
      "characteristic_length", *std::min_element(p.domain.begin(), p.domain.end()),
      "length in m for the Reynolds number (default: smallest domain edge)", Bounds::positive());
  p.body_force = s.vec3("body_force", {0, 0, 0}, "uniform acceleration of the fluid in m/s^2");
  if (auto c = s.optional_section("mean_velocity_control",
                                  "uniform force that holds the mean fluid velocity")) {
    p.control.enabled = true;
    p.control.target = c->vec3("target", {0, 0, 0}, "mean fluid velocity to hold, m/s");
    p.control.gain =
        c->get<double>("gain", 0.5, "proportional gain per update", Bounds::closed(0.0, 1.0));
    p.control.integral_gain =
        c->get<double>("integral_gain", 0.05, "integral gain per update", Bounds::closed(0.0, 0.5));
    p.control.interval =
        c->get<double>("interval", 0.0, "seconds between controller updates (0: every step)",
                       Bounds::non_negative());
    p.control.feed_forward = c->get<bool>(
        "feed_forward", true, "start from the exact force that balances the bodies' net weight");
    c->finish();
  }
  p.loads = s.choice("loads", "penalization", {"penalization", "momentum_exchange"},
                     "hydrodynamic load on bodies: from the penalization (conserves momentum) "
                     "or by momentum exchange") == "momentum_exchange"
                ? LoadMethod::momentum_exchange
                : LoadMethod::penalization;
  p.decomposition =
      s.choice("decomposition", "regular", {"regular", "balanced"},
               "how the lattice is split over the fluid ranks: regular (equal blocks) or "
               "balanced (the cuts of each axis placed so that every rank gets the same work of "
               "the initial bodies; docs/scaling.md)") == "balanced"
          ? DecompositionKind::balanced
          : DecompositionKind::regular;
  p.covered_cell_weight = s.get<double>(
      "covered_cell_weight", 10.0,
      "work of a lattice cell a body covers (band and interior: porosity, penalization, load "
      "sums) in plain fluid cells, for decomposition: balanced (measured: docs/scaling.md)",
      Bounds::at_least(1.0));
  {
    auto b = s.section_or_defaults("boundaries", "per-face boundary conditions");
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
  if (p.control.interval > 0)
    p.control.every = std::max(1L, std::lround(p.control.interval / p.units.dt));
  const UnitConverter& u = p.units;
  if (p.tau < UnitLimits{}.min_tau) s.fail("tau", u.check());
  if (p.hydrodynamic_radius == "calibrated" && !band_radius_excess_cells(p.tau, p.porosity_lookup))
    s.fail("hydrodynamic_radius",
           "the band's radius excess is calibrated for tau in " + band_calibration_range() +
               " with the " + p.porosity_lookup + " lookup; tau is " + std::to_string(p.tau) +
               ": set hydrodynamic_radius: nominal, or measure it (tools/calibrate_band.py)");
  if (const std::string m = u.check(); !m.empty()) s.fail("characteristic_velocity", m);
  p.output = parse_fluid_output(s, p.units, p.cells);
  s.finish();
  return p;
}

}  // namespace lbdem
