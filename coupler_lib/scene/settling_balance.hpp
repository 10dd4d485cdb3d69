#pragma once
// The force balance of a triply periodic settling box, computed identically by both programs
// (docs/method.md Eq. (11)).
//
// Each body carries its net weight W_k = (rho_k - rho_f) V_k g (gravity and buoyancy on the
// DEM side). In a triply periodic box nothing carries the total W = sum_k W_k, so a uniform
// compensating force density f = -W / V_box acts on the whole box: the mean pressure gradient
// a bottom wall would provide. The lattice applies f to its nodes, but on nodes inside a body
// the penalization resets the velocity to the body's every step, so that part never reaches
// the fluid nor (through the momentum exchange, which sums boundary links only) the body.
// The body therefore gets its share f V_k explicitly on the DEM side; fluid and bodies then
// receive -W in total and the mean momentum stays zero.
#include <array>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

struct SettlingBalance {
  bool active = false;                    // triply periodic, with bodies and gravity
  std::array<double, 3> net_weight{};     // W, N
  std::array<double, 3> force_density{};  // f = -W / V_box, N/m^3
};

SettlingBalance settling_balance(const Scene& scene, const std::vector<Shape>& shapes);

}  // namespace lbdem
