#pragma once
// The `fluid.output:`, `fluid.stability:` and `fluid.validation:` keys of a scene: what the
// fluid writes (fields as HDF5 + XDMF, a CSV time series of domain means), how often it checks
// itself for divergence, and which analytic solution it compares against at the end.
//
// Nothing here is on unless the scene asks: without `output:` no file is written, without
// `output.fields:` no field is computed, without `validation:` no error is computed. The
// stability watch is the exception: it is on by default (every 100 steps) because a diverged
// run that goes on silently wastes the whole allocation; `stability: {interval: 0}` turns it off.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/scene/choices.hpp"
#include "coupler_lib/scene/units.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

// A plane of nodes normal to `axis` through the node nearest to `position`.
struct FieldSlice {
  int axis = 2;         // 0, 1, 2 for x, y, z
  double position = 0;  // m, as given in the scene
  int index = 0;        // derived: global node index along `axis`
  std::string name;     // derived: "slice_z12" (axis and node index), used in file names
};

struct FieldOutputParams {
  double interval = 0;  // s of simulated time between field outputs
  long every = 1;       // derived: steps between field outputs
  bool velocity = true;
  bool density = false;
  bool pressure = false;
  int stride = 1;      // write every stride-th node along each axis
  bool volume = true;  // write the (subsampled) 3D volume
  std::vector<FieldSlice> slices;
  bool double_precision = false;  // file type: float64 instead of float32
};

struct SeriesOutputParams {
  double interval = 0;  // s of simulated time between rows
  long every = 1;       // derived: steps between rows
};

struct StabilityParams {
  long interval = 100;    // steps between checks; 0 switches the watch off
  double max_mach = 0.3;  // |u| / c_s above which the run stops
  std::string last_good;  // file of the last good state; empty: "<scene name>_last_good.h5"
};

struct ValidationParams {
  ValidationCase kind = ValidationCase::poiseuille;
  std::string name;                // "poiseuille", "couette", "taylor_green"
  double amplitude = 0;            // taylor_green: initial velocity amplitude, m/s
  std::array<int, 2> plane{0, 1};  // taylor_green: the two axes the vortex lies in
  double tolerance = 0;            // if > 0: the run fails (exit 4) when the error exceeds it
};

struct FluidOutputParams {
  std::string directory = ".";  // where every output file goes (created if missing); derived:
                                // resolved against the scene file's folder
  std::optional<FieldOutputParams> fields;
  std::optional<SeriesOutputParams> series;
  StabilityParams stability;
  std::optional<ValidationParams> validation;

  bool writes_files() const { return fields || series; }
};

// Reads the three optional sub-sections of `fluid:`. `units` and `cells` are the already
// resolved lattice (time step for the intervals, node counts for slices).
// The schemas of fluid.output, fluid.stability and fluid.validation.
const MappingSchema& fluid_output_schema();
const MappingSchema& stability_schema();
const MappingSchema& validation_schema();
FluidOutputParams parse_fluid_output(Section& fluid, const UnitConverter& units,
                                     const std::array<int, 3>& cells);

}  // namespace lbdem
