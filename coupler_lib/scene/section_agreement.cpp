#include "coupler_lib/scene/section_agreement.hpp"

#include <string>

namespace lbdem {

namespace {

std::string periodic_axes(const std::array<bool, 3>& periodic) {
  std::string s;
  for (int a = 0; a < 3; ++a)
    if (periodic[a]) s += axis_name(a);
  return s.empty() ? "none" : s;
}

}  // namespace

void check_sections_agree(const Scene& scene, const Section& dem) {
  if (!scene.dem) return;
  if (!scene.fluid && !scene.dem->has_box)
    dem.fail("box",
             "required when the scene has no fluid section (the DEM box is otherwise "
             "[0, fluid.domain])");
  if (!scene.coupled()) return;
  const std::array<bool, 3> fluid{scene.fluid->periodic(0), scene.fluid->periodic(1),
                                  scene.fluid->periodic(2)};
  for (int a = 0; a < 3; ++a) {
    if (scene.dem->periodic[a] == fluid[a]) continue;
    dem.fail("periodic", "periodic on '" + periodic_axes(scene.dem->periodic) +
                             "' but fluid.boundaries on '" + periodic_axes(fluid) +
                             "': they disagree along " + axis_name(a) +
                             "; both sides must be periodic on the same axes");
  }
  if (scene.dem->buoyancy_fluid_density > 0)
    dem.fail("buoyancy_fluid_density",
             "only for DEM-only scenes; in a coupled run the fluid side supplies buoyancy");
}

}  // namespace lbdem
