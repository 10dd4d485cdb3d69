#pragma once
// Scenes written inline in a DEM test: parsed as a file "t.yaml" would be, turned into the
// DEM setup exactly as dem_app does, and the first validation error's message.
#include <string>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/setup/dem_setup.hpp"

namespace lbdem::test {

// The scene the bodies-file tests (CSV and HDF5) add their bodies to: a box and two shapes.
inline const std::string kBodiesFileBase = R"(
name: t
time: {end: 0.1}
dem:
  box: {lo: [0, 0, 0], hi: [0.1, 0.1, 0.1]}
shapes:
  - {name: ball, kind: sphere, diameter: 0.01}
  - {name: cube, kind: cube, edge: 0.01, clump: {method: surface, grid: 3}}
)";

inline Scene parse(const std::string& text) {
  return parse_scene(Section::load_string(text, "t.yaml"), 0);
}

inline DemSetup setup_of(const std::string& text) {
  const Scene s = parse(text);
  return make_dem_setup(s, build_scene_shapes(s), false);
}

// "" when the scene passes.
inline std::string error_of(const std::string& text) {
  try {
    validate_dem_setup(setup_of(text));
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace lbdem::test
