#include "coupler_lib/scene/dem_section.hpp"

namespace lbdem {

DemParams parse_dem(Section& s) {
  DemParams p;
  p.gravity = s.vec3("gravity", {0, 0, -9.81}, "gravitational acceleration in m/s^2");
  p.dt = s.get<double>("dt", 0.0, "DEM time step in s (0: a fraction of the Rayleigh time)",
                       Bounds::non_negative());
  s.finish();
  return p;
}

}  // namespace lbdem
