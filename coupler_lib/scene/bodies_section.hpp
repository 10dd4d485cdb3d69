#pragma once
// The `shapes:` catalogue and the `bodies:` list of a scene.
#include <array>
#include <string>
#include <vector>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct ShapeParams {
  std::string name;
  std::string kind;  // sphere | cube | cuboid | ellipsoid | stl
  double size = 0;   // m: sphere diameter, cube edge
};

struct BodyParams {
  int shape = 0;                                  // index into the catalogue
  std::array<double, 3> position{};               // m, centre of mass
  std::array<double, 4> orientation{1, 0, 0, 0};  // quaternion (w, x, y, z), body -> space
  std::array<double, 3> velocity{};               // m/s
  std::array<double, 3> angular_velocity{};       // rad/s
  double density = 0;                             // kg/m^3
};

struct BodiesParams {
  std::vector<ShapeParams> shapes;
  std::vector<BodyParams> bodies;
};

BodiesParams parse_bodies(Section& root);

}  // namespace lbdem
