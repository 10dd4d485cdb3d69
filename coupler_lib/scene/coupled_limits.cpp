#include "coupler_lib/scene/coupled_limits.hpp"

#include <sstream>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

void check_coupled_limits(const Scene& scene) {
  if (!scene.coupled()) return;
  const double rho_f = scene.fluid->density;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const double ratio = scene.bodies[i].density / rho_f;
    if (ratio >= kMinDensityRatio) continue;
    // The body's own covered fluid enters its equation of motion explicitly (one step late);
    // that iteration amplifies by about rho_f / rho_p per step (docs/method-loads.md, 3).
    std::ostringstream m;
    m << scene.file << ": body " << i << " (bodies / density): density " << scene.bodies[i].density
      << " kg/m^3 is " << ratio << " times fluid.density " << rho_f
      << " kg/m^3; the explicit coupling is unstable below a ratio of " << kMinDensityRatio
      << " (measured: stable at 0.2, diverging at 0.1). Raise the body density to at least "
      << kMinDensityRatio * rho_f << " kg/m^3; lighter bodies (bubbles) need an implicit "
      << "treatment of the covered fluid, which this program does not have";
    throw SceneError(m.str());
  }
}

}  // namespace lbdem
