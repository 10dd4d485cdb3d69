#pragma once
// Building a DEM engine from scene YAML text or a scene file, as dem_app does.
#include <filesystem>
#include <memory>
#include <string>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/engine/lammps_engine.hpp"
#include "dem_app/setup/dem_setup.hpp"

namespace lbdem::test {

inline Scene scene_from_text(const std::string& text) {
  return parse_scene(Section::load_string(text, "test.yaml"), 0);
}

inline DemSetup setup_from_scene(const Scene& scene, bool external_loads = false) {
  DemSetup s = make_dem_setup(scene, build_scene_shapes(scene), external_loads);
  // LAMMPS writes its errors only to its log (no exceptions in this build).
  s.lammps_log = (std::filesystem::temp_directory_path() / "lbdem_dem_test_lammps.log").string();
  return s;
}

// Scene files of the validation cases live in configs/dem/validation.
inline std::string config_path(const std::string& name) {
  return std::string(LBDEM_SOURCE_DIR) + "/configs/dem/" + name;
}

}  // namespace lbdem::test
