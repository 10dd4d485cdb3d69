#pragma once
// The `fluid:` section of a scene: lattice, fluid properties, boundaries, forcing, output.
#include <array>
#include <string>

#include "coupler_lib/scene/units.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct FluidParams {
  std::array<double, 3> domain{};  // m, box size
  std::array<int, 3> cells{};      // derived: domain / dx
  double dx = 0;                   // m
  double density = 1000;           // kg/m^3
  double viscosity = 1e-6;         // kinematic, m^2/s
  double tau = 0.6;
  std::string precision = "double";
  UnitConverter units;
};

FluidParams parse_fluid(Section& s);

}  // namespace lbdem
