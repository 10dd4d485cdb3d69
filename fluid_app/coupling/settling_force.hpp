#pragma once
// The fluid's part of the settling balance (coupler_lib/scene/settling_balance.hpp): the
// compensating force density of a triply periodic box as a uniform lattice force per node.
#include <array>
#include <string>
#include <vector>

#include "coupler_lib/scene/settling_balance.hpp"

namespace lbdem {

struct SettlingForce {
  bool active = false;
  std::array<double, 3> fluid_force_lattice{};  // per node, lattice units
  std::array<double, 3> net_weight{};           // W, N (what the DEM side applies)
  std::string description;
};

SettlingForce settling_force(const Scene& scene, const std::vector<Shape>& shapes);

}  // namespace lbdem
