#include "dem_app/contact/restitution_map.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lbdem {

double tsuji_alpha(double p) {
  // Tsuji, Tanaka & Ishida (1992), as coded in LAMMPS pair granular (damping tsuji).
  return 1.2728 - 4.2783 * p + 11.087 * p * p - 22.348 * std::pow(p, 3) + 27.467 * std::pow(p, 4) -
         18.022 * std::pow(p, 5) + 4.8218 * std::pow(p, 6);
}

double restitution_for_alpha(double alpha) {
  // x: overlap, v: its rate; the contact ends when the overlap returns to zero. LAMMPS does
  // not clip the (attractive) damping force at the end of the contact, and neither do we.
  auto accel = [alpha](double x, double v) {
    const double xp = x > 0 ? x : 0.0;
    return -xp * std::sqrt(xp) - alpha * std::sqrt(std::sqrt(xp)) * v;
  };
  constexpr double h = 2e-4;  // contact lasts ~3.2 time units: ~16000 steps, e to 1e-7
  double x = 0, v = 1;
  for (int n = 0; n < 1000000; ++n) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (n > 0 && xn <= 0) {
      const double f = x / (x - xn);  // linear interpolation to the end of contact
      return -(v + f * (vn - v));
    }
    x = xn;
    v = vn;
  }
  throw std::runtime_error("restitution_for_alpha: contact did not end");
}

double min_tsuji_restitution() {
  return restitution_for_alpha(tsuji_alpha(0.0));
}
double max_tsuji_restitution() {
  return restitution_for_alpha(tsuji_alpha(1.0));
}

double tsuji_parameter_for(double e) {
  const double lo_e = min_tsuji_restitution(), hi_e = max_tsuji_restitution();
  if (!(e >= lo_e && e <= hi_e))
    throw std::invalid_argument("restitution " + std::to_string(e) +
                                " cannot be reached with LAMMPS damping tsuji; admissible: [" +
                                std::to_string(lo_e) + ", " + std::to_string(hi_e) +
                                "] or exactly 1 (no damping)");
  // Both maps are monotone: e falls with alpha, alpha falls with p; bisect on p directly.
  double lo = 0, hi = 1;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (restitution_for_alpha(tsuji_alpha(mid)) < e)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace lbdem
