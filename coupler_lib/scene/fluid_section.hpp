#pragma once
// The `fluid:` section of a scene: lattice, fluid properties, boundaries, forcing.
//
//   fluid:
//     domain: [0.01, 0.01, 0.02]      # m
//     dx: 2.5e-4                      # m  (or resolution: {length: 0.001, cells: 4})
//     viscosity: 1.0e-6               # m^2/s
//     density: 1000                   # kg/m^3
//     tau: 0.8
//     precision: double               # or float
//     porosity_lookup: nearest        # (the paper's) or trilinear: how bodies map to the lattice
//     hydrodynamic_radius: calibrated # or nominal: remove the band's measured radius excess
//     characteristic_velocity: 0.05   # m/s, expected flow speed: logs Ma and Re, refuses Ma > 0.3
//     characteristic_length: 0.001    # m, for Re (default: smallest domain edge)
//     body_force: [0, 0, -9.81]       # m/s^2 acceleration of the fluid (uniform)
//     mean_velocity_control: {target: [0, 0, 0], gain: 0.5, integral_gain: 0.05,
//                             interval: 0, feed_forward: true}
//     loads: penalization             # or momentum_exchange (docs/method-loads.md)
//     decomposition: regular          # or balanced: cuts by the bodies' work (docs/scaling.md)
//     covered_cell_weight: 10         # work of a covered cell in fluid cells (balanced)
//     rebalance_above: 1.1            # recut above this measured imbalance (balanced)
//     rebalance_interval: 0           # s between in-run rebalancing checks (0: at restarts only)
//     boundaries:
//       x_min: periodic               # periodic faces must be paired
//       x_max: periodic
//       y_min: {type: pressure, pressure: 0}   # Pa, gauge
//       y_max: {type: pressure, pressure: 0}
//       z_min: wall
//       z_max: {type: moving_wall, velocity: [0.01, 0, 0]}
#include <array>
#include <string>

#include "coupler_lib/scene/choices.hpp"
#include "coupler_lib/scene/fluid_output_section.hpp"
#include "coupler_lib/scene/units.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

// One face of the box. Faces are indexed 2*axis + side (side 0 = min, 1 = max):
// x_min, x_max, y_min, y_max, z_min, z_max.
struct FaceBoundary {
  FaceType type = FaceType::periodic;
  std::array<double, 3> velocity{};  // m/s, moving_wall only (tangential part is what counts)
  double pressure = 0;               // Pa relative to the reference pressure, pressure only
};

// PI controller on a uniform body force that holds the mean fluid velocity at `target`
// (hindered settling in a triply periodic box: the force that balances the bodies' weight).
// Every `interval` seconds (0: every step) with e = target - <u>, lattice units:
//   sum += e,  F = F_scene + F_ff + gain e + integral_gain sum.
// The paper's update f <- f - K_p <v> every 1e-4 s is {gain: 0, integral_gain: K_p = 0.01,
// interval: 1e-4}; feed_forward adds the exact balancing force of a settling box (F_ff).
struct MeanVelocityControl {
  bool enabled = false;
  std::array<double, 3> target{};  // m/s
  double gain = 0.5;               // proportional gain, per update (1 = dead-beat without bodies)
  double integral_gain = 0.05;     // integral gain, per update
  double interval = 0;             // s between updates; 0: every step
  long every = 1;                  // derived: steps between updates
  bool feed_forward = true;        // start from the settling balance's exact force
};

struct FluidParams {
  std::array<double, 3> domain{};  // m, box size
  std::array<int, 3> cells{};      // derived: domain / dx
  double dx = 0;                   // m
  double density = 1000;           // kg/m^3
  double viscosity = 1e-6;         // kinematic, m^2/s
  double tau = 0.6;
  Precision precision = Precision::float64;
  // How HLBM nodes read a body's reference porosity: nearest | trilinear (fluid_app/hlbm);
  // nearest by default, chosen from the settling numbers of docs/validation.md.
  PorosityLookup porosity_lookup = PorosityLookup::nearest;
  // nominal: the fluid sees the body's true surface (the paper's construction); calibrated: the
  // surface moved inward by the band's measured hydrodynamic-radius excess at this tau
  // (coupler_lib/scene/band_calibration.hpp, docs/method.md "Hydrodynamic radius calibration").
  HydrodynamicRadius hydrodynamic_radius = HydrodynamicRadius::calibrated;
  double characteristic_velocity = 0;  // m/s, 0 = not given
  double characteristic_length = 0;    // m
  std::array<double, 3> body_force{};  // m/s^2, uniform acceleration of the fluid
  MeanVelocityControl control;
  LoadMethod loads = LoadMethod::penalization;
  DecompositionKind decomposition = DecompositionKind::regular;
  double covered_cell_weight = 10;      // work of a covered cell / a fluid cell (balanced split)
  double rebalance_above = 1.1;         // recut when the measured imbalance is above (balanced)
  double rebalance_interval = 0;        // s between in-run checks (coupled, balanced); 0: none
  std::array<FaceBoundary, 6> faces{};  // default: triply periodic
  UnitConverter units;
  FluidOutputParams output;  // fluid.output, fluid.stability, fluid.validation

  bool periodic(int axis) const { return faces[2 * axis].type == FaceType::periodic; }
};

const MappingSchema& fluid_schema();
FluidParams parse_fluid(Section& s);

const char* face_name(int face);  // "x_min", ..., "z_max"
const char* face_type_name(FaceType t);

}  // namespace lbdem
