#pragma once
// The `bodies:` list of a scene: where bodies start and how they move initially. An entry is
// one body, a CSV file of bodies (`file:`, bodies_file.hpp) or a generator (`generate: lattice |
// random`) that places `count` bodies (or enough for a `solid_fraction`) without overlap inside a
// region, with random orientations drawn from a seed. Generators are expanded while parsing,
// deterministically (own RNG arithmetic, no implementation-defined distributions), so both
// binaries get the same list.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/geometry/shape_kinds.hpp"
#include "coupler_lib/scene/choices.hpp"
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

// What a generator entry asks for.
struct BodyGenerator {
  BodyPattern pattern = BodyPattern::lattice;
  int shape = 0;
  double density = 0;
  std::array<double, 3> lo{}, hi{};  // region the bodies lie in entirely
  long count = 0;
  double min_distance = 0;     // centre-to-centre, m
  double bounding_radius = 0;  // m, keeps bodies inside the region
  std::uint64_t seed = 1;
  bool random_orientation = true;
  std::array<double, 4> orientation{1, 0, 0, 0};
  std::array<double, 3> velocity{};
  std::array<double, 3> angular_velocity{};
};

// Places the bodies of a generator; throws SceneError (via `where`) when they do not fit.
std::vector<BodyParams> generate_bodies(const BodyGenerator& g, const Section& where);

// The schema of one entry of `bodies:` (a body, a generator or a bodies file).
const MappingSchema& body_schema();
std::vector<BodyParams> parse_bodies(Section& root, const std::vector<ShapeParams>& shapes);

}  // namespace lbdem
