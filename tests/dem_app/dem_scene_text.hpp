#pragma once
// Scenes written inline in a DEM test: parsed as a file "t.yaml" would be, turned into the
// DEM setup exactly as dem_app does, and the first validation error's message.
#include <string>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/dem_setup.hpp"

namespace lbdem::test {

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
