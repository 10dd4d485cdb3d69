#pragma once
// What went wrong when the stability watch stops a run, and the one message that says where,
// when, which quantity, the likely cause and what to change in the scene.
#include <array>
#include <string>

#include "coupler_lib/scene/units.hpp"

namespace lbdem {

// Ordered by severity: a check reports the worst kind found anywhere.
enum class Instability { none = 0, mach = 1, density = 2, not_finite = 3 };

struct InstabilityReport {
  Instability kind = Instability::none;
  std::array<int, 3> cell{};  // global node index of the worst (Mach) or first (others) node
  double rho = 0;             // lattice density there
  std::array<double, 3> u{};  // lattice velocity there
  double mach = 0;            // |u| / c_s there
  long long bad_cells = 0;    // nodes of this kind in the whole domain
  long step = 0;
  double time = 0;           // s
  long last_good_step = -1;  // -1: no check passed before
  double last_good_time = 0;
  double last_good_mach = 0;  // max Mach at the last good check
  double max_mach = 0.3;      // the scene's limit
};

// The full diagnosis (several lines). `last_good_file` is empty when nothing could be written.
std::string describe_instability(const InstabilityReport& r, const UnitConverter& units,
                                 const std::string& last_good_file);

}  // namespace lbdem
