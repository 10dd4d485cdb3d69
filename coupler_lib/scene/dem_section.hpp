#pragma once
// The `dem:` section of a scene: contact model, walls, gravity, DEM time step.
#include <array>
#include <string>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct DemParams {
  std::array<double, 3> gravity{0, 0, -9.81};  // m/s^2
  double dt = 0;                               // s; 0 = from the Rayleigh time
};

DemParams parse_dem(Section& s);

}  // namespace lbdem
