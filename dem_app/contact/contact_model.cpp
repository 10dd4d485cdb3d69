#include "dem_app/contact/contact_model.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "dem_app/contact/restitution_map.hpp"

namespace lbdem {

std::string ContactModel::lammps_arguments() const {
  std::ostringstream s;
  s.precision(17);
  // hertz/material E damping nu: the second value is the damping parameter.
  s << "hertz/material " << material.young_modulus << " " << (undamped ? 0.0 : tsuji_parameter)
    << " " << material.poisson_ratio << " tangential mindlin NULL 1.0 " << material.friction
    << " damping " << (undamped ? "velocity" : "tsuji");
  return s.str();
}

ContactModel make_contact_model(const DemMaterial& m, const std::string& where) {
  ContactModel c;
  c.material = m;
  if (m.restitution >= 1.0) {
    c.undamped = true;
    return c;
  }
  try {
    c.tsuji_parameter = tsuji_parameter_for(m.restitution);
  } catch (const std::invalid_argument& e) {
    throw SceneError(where + ": dem.material.restitution: " + e.what());
  }
  return c;
}

double hertz_contact_time(double radius, double mass, double speed, const DemMaterial& m) {
  // Two like spheres: E* = E / (2 (1 - nu^2)), R_eff = r / 2, m_eff = m / 2 (Hertz theory,
  // e.g. Johnson, Contact Mechanics, sec. 11.4).
  const double e_star = m.young_modulus / (2.0 * (1.0 - m.poisson_ratio * m.poisson_ratio));
  const double m_eff = 0.5 * mass, r_eff = 0.5 * radius;
  return 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * speed), 0.2);
}

}  // namespace lbdem
