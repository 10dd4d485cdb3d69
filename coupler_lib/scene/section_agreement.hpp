#pragma once
// Checks between the sections of a scene that a program would otherwise make only at run time
// (the DEM after the coupling handshake, its set-up): made when the scene is read, so that both
// programs' --check refuse the scene with the same message, naming file, line and key.
#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

// `dem`: the scene's dem section, where the messages point. Throws SceneError when
// * a coupled scene's dem.periodic and fluid.boundaries are periodic on different axes (the
//   bodies would wrap where the fluid has a wall, or stop where the fluid wraps);
// * a coupled scene sets dem.buoyancy_fluid_density (the fluid side supplies buoyancy);
// * a DEM-only scene has no dem.box (there is no fluid domain to take it from).
void check_sections_agree(const Scene& scene, const Section& dem);

}  // namespace lbdem
