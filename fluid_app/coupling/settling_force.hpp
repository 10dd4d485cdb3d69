#pragma once
// Which force the fluid receives in a coupled scene so that gravity and buoyancy are
// consistent with how the box is driven (README, "Forces on bodies and fluid").
//
// The fluid carries no gravity of its own: its hydrostatic pressure gradient is left out, so
// every body gets its weight minus the buoyancy of the displaced fluid explicitly on the DEM
// side, W_k = (rho_k - rho_f) V_k g. In a closed box the walls carry that weight. In a triply
// periodic box nothing would, and fluid and bodies would fall together forever; the fluid
// then gets the opposite of the bodies' total net weight as a uniform force density,
//   f = - sum_k W_k / V_box,
// so the total momentum of fluid plus bodies stays zero (the "compensating force" of the
// paper's hindered-settling section; with fluid.mean_velocity_control the PI controller adds
// its correction to this feed-forward).
#include <array>
#include <string>
#include <vector>

#include "coupler_lib/scene/scene.hpp"
#include "coupler_lib/shapes/shape.hpp"

namespace lbdem {

struct SettlingForce {
  bool active = false;
  std::array<double, 3> fluid_force_lattice{};  // per cell, lattice units
  std::array<double, 3> net_weight{};           // N, sum over bodies
  std::string description;
};

SettlingForce settling_force(const Scene& scene, const std::vector<Shape>& shapes);

}  // namespace lbdem
