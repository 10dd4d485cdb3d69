#pragma once
// The contact law handed to LAMMPS (paper, appendix "DEM"): Hertz normal force with the
// material's effective modulus, Tsuji damping calibrated to the requested restitution, and
// Mindlin tangential friction with k_t = 8 G_eff a and tangential damping equal to the normal
// one (ratio 1), capped by Coulomb's mu |F_n|. The same law acts at plane walls.
#include <string>

#include "coupler_lib/scene/dem_section.hpp"

namespace lbdem {

struct ContactModel {
  DemMaterial material;
  double tsuji_parameter = 0;  // p of `damping tsuji`; unused when undamped
  bool undamped = false;       // e = 1

  // The model arguments shared by `pair_coeff * *` and `fix wall/gran granular`.
  std::string lammps_arguments() const;
};

// Resolves the restitution map; throws SceneError naming the key when e is out of reach.
ContactModel make_contact_model(const DemMaterial& m, const std::string& where);

// Duration of a Hertz binary collision of two equal spheres (radius r, masses m) at
// approach speed v, without damping: t_c = 2.868 (m_eff^2 / (R_eff E*^2 v))^(1/5).
double hertz_contact_time(double radius, double mass, double speed, const DemMaterial& m);

}  // namespace lbdem
