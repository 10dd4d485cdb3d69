#include "dem_app/lubrication_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lbdem {

SqueezeCoefficients squeeze_coefficients(double a1, double a2) {
  if (a2 <= 0) return {1.0, 0.2};  // plane wall: the beta -> infinity limit
  const double b = a2 / a1, p = 1 + b;
  return {b * b / (p * p), b * (1 + 7 * b + b * b) / (5 * p * p * p)};
}

double squeeze_lambda(const SqueezeCoefficients& g, double a1, double h) {
  return g.g1 * a1 / h + g.g2 * std::log(a1 / h);
}

double lubrication_resistance(const LubricationLaw& law, double a1, double a2, double gap) {
  if (gap >= law.cutoff) return 0;
  const SqueezeCoefficients g = squeeze_coefficients(a1, a2);
  const double h = std::max(gap, law.min_gap);
  return 6 * std::numbers::pi * law.viscosity * a1 *
         (squeeze_lambda(g, a1, h) - squeeze_lambda(g, a1, law.cutoff));
}

SlidingResistance wall_sliding_resistance(const LubricationLaw& law, double a, double gap) {
  if (gap >= law.cutoff) return {};
  // ln(a / h) - ln(a / h_c)
  const double l = std::log(law.cutoff / std::max(gap, law.min_gap));
  const double mu = law.viscosity, pi = std::numbers::pi;
  return {6 * pi * mu * a * 8.0 / 15.0 * l, 6 * pi * mu * a * a * 2.0 / 15.0 * l,
          8 * pi * mu * a * a * a * 2.0 / 5.0 * l};
}

}  // namespace lbdem
