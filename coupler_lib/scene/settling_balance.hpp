#pragma once
// The force balance of a triply periodic settling box, computed identically by both programs
// (docs/method.md Eq. (11)).
//
// Each body carries its net weight W_k = (rho_k - rho_f) V_k g (gravity and buoyancy on the
// DEM side). In a triply periodic box nothing carries the total W = sum_k W_k, so a uniform
// compensating force density f = -W / V_box acts on the whole box: the mean pressure gradient
// a bottom wall would provide. The lattice applies it to every node, those inside bodies
// included; a body receives the part on its nodes through the penalization load (the
// interior's extra momentum is removed by the penalization in the next step and charged to
// the body, docs/method-loads.md). The external forces then sum to N f dx^3 + W = 0 exactly
// and the momentum of fluid plus bodies is conserved.
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
