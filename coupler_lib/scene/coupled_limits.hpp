#pragma once
// Limits of the explicit coupling that a scene can be checked against before it runs
// (docs/stability.md).
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// Smallest body-to-fluid density ratio the explicit treatment of the fluid covered by a body
// stays stable at (docs/method-loads.md, section 3: stable at 0.2, diverging at 0.1).
inline constexpr double kMinDensityRatio = 0.2;

// Throws SceneError naming the file, the body and what to change when a coupled scene has a
// body lighter than kMinDensityRatio times the fluid.
void check_coupled_limits(const Scene& scene);

}  // namespace lbdem
