#pragma once
// Map from the user's coefficient of restitution e to the parameter of LAMMPS's
// `damping tsuji` (29Sep2021 has no `damping coeff_restitution`).
//
// LAMMPS's Hertz/material normal force with Tsuji damping is
//   F = k a delta - alpha sqrt(m k a) v_n,   a = sqrt(R delta),  k = 4/3 E*,
//   alpha = poly(p) (Tsuji et al. 1992 fit, evaluated by LAMMPS from the pair_coeff value p).
// In units m = k sqrt(R) = v_0 = 1 a collision obeys x'' = -x^(3/2) - alpha x^(1/4) x',
// so the restitution depends on alpha alone (not on speed, size, mass or stiffness). We
// integrate that equation to get e(alpha) and invert both maps, instead of trusting the fit:
// LAMMPS given p = 0.9 measures e = 0.928.
namespace lbdem {

// Tsuji's polynomial alpha(p) as LAMMPS applies it to the pair_coeff value p.
double tsuji_alpha(double p);

// Restitution of a Hertz collision with damping prefactor alpha (RK4 on the scaled equation).
double restitution_for_alpha(double alpha);

// Smallest and largest e reachable with p in [0, 1].
double min_tsuji_restitution();
double max_tsuji_restitution();

// The p in [0, 1] that gives restitution e; throws std::invalid_argument outside the range.
double tsuji_parameter_for(double e);

}  // namespace lbdem
