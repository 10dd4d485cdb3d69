#pragma once
// The `bodies:` list of a scene: where bodies start and how they move initially.
#include <array>
#include <string>
#include <vector>

#include "coupler_lib/scene/shapes_section.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct BodyParams {
  int shape = 0;                                  // index into the catalogue
  std::array<double, 3> position{};               // m, centre of mass
  std::array<double, 4> orientation{1, 0, 0, 0};  // quaternion (w, x, y, z), shape -> space
  std::array<double, 3> velocity{};               // m/s
  std::array<double, 3> angular_velocity{};       // rad/s
  double density = 0;                             // kg/m^3
};

std::vector<BodyParams> parse_bodies(Section& root, const std::vector<ShapeParams>& shapes);

}  // namespace lbdem
