#include "dem_app/lubrication/lubrication_law.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lbdem {

namespace {

// The film the correction stands for lies between contact and h_c. Once the surfaces touch
// (gap <= 0) the DEM contact begins and alone sets the collision: the correction is off there
// (docs/lubrication.md, "At contact").
bool in_film(const LubricationLaw& law, double gap) {
  return gap > 0 && gap < law.cutoff;
}

}  // namespace

SqueezeCoefficients squeeze_coefficients(double a1, double a2) {
  if (a2 <= 0) return {1.0, 0.2};  // plane wall: the beta -> infinity limit
  const double b = a2 / a1, p = 1 + b;
  return {b * b / (p * p), b * (1 + 7 * b + b * b) / (5 * p * p * p)};
}

double squeeze_lambda(const SqueezeCoefficients& g, double a1, double h) {
  return g.g1 * a1 / h + g.g2 * std::log(a1 / h);
}

double lubrication_resistance(const LubricationLaw& law, double a1, double a2, double gap) {
  if (!in_film(law, gap)) return 0;
  const SqueezeCoefficients g = squeeze_coefficients(a1, a2);
  const double h = std::max(gap, law.min_gap);
  return 6 * std::numbers::pi * law.viscosity * a1 *
         (squeeze_lambda(g, a1, h) - squeeze_lambda(g, a1, law.cutoff));
}

SlidingResistance wall_sliding_resistance(const LubricationLaw& law, double a, double gap) {
  if (!in_film(law, gap)) return {};
  // ln(a / h) - ln(a / h_c)
  const double l = std::log(law.cutoff / std::max(gap, law.min_gap));
  const double mu = law.viscosity, pi = std::numbers::pi;
  return {6 * pi * mu * a * 8.0 / 15.0 * l, 6 * pi * mu * a * a * 2.0 / 15.0 * l,
          8 * pi * mu * a * a * a * 2.0 / 5.0 * l};
}

PairSlidingResistance pair_sliding_resistance(const LubricationLaw& law, double a1, double a2,
                                              double gap) {
  if (!in_film(law, gap)) return {};
  const double l = std::log(law.cutoff / std::max(gap, law.min_gap));
  const double mu = law.viscosity, pi = std::numbers::pi;
  const double b = a2 / a1, p = 1 + b;
  auto g_b = [](double beta) { return -beta * (4 + beta) / (5 * (1 + beta) * (1 + beta)); };
  auto g_c = [](double beta) { return 2 * beta / (5 * (1 + beta)); };
  const double g_a = 4 * b * (2 + b + 2 * b * b) / (15 * p * p * p);
  const double g_c12 = 4 * b * b / (5 * p * p * p * p);
  const double s = (a1 + a2) / (a1 + a2 + gap);  // see the header: exact at the actual distance
  return {6 * pi * mu * a1 * g_a * l * s * s,
          4 * pi * mu * a1 * a1 * g_b(b) * l * s,
          4 * pi * mu * a2 * a2 * g_b(1 / b) * l * s,
          8 * pi * mu * a1 * a1 * a1 * g_c(b) * l,
          pi * mu * (a1 + a2) * (a1 + a2) * (a1 + a2) * g_c12 * l,
          8 * pi * mu * a2 * a2 * a2 * g_c(1 / b) * l};
}

namespace {

Vec3 cross(const Vec3& x, const Vec3& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

// (I - d d) x
Vec3 tangential(const Vec3& d, const Vec3& x) {
  const double n = d[0] * x[0] + d[1] * x[1] + d[2] * x[2];
  return {x[0] - n * d[0], x[1] - n * d[1], x[2] - n * d[2]};
}

}  // namespace

PairSlidingLoads pair_sliding_loads(const PairSlidingResistance& r, const Vec3& d, const Vec3& du,
                                    const Vec3& w1, const Vec3& w2) {
  const Vec3 ut = tangential(d, du), w1t = tangential(d, w1), w2t = tangential(d, w2);
  const Vec3 spin = cross(
      d, {r.coupling1 * w1[0] + r.coupling2 * w2[0], r.coupling1 * w1[1] + r.coupling2 * w2[1],
          r.coupling1 * w1[2] + r.coupling2 * w2[2]});
  const Vec3 shear = cross(du, d);
  PairSlidingLoads out;
  for (int k = 0; k < 3; ++k) {
    out.force1[k] = -r.translation * ut[k] - spin[k];
    out.torque1[k] = -r.coupling1 * shear[k] - r.rotation11 * w1t[k] - r.rotation12 * w2t[k];
    out.torque2[k] = -r.coupling2 * shear[k] - r.rotation12 * w1t[k] - r.rotation22 * w2t[k];
  }
  return out;
}

}  // namespace lbdem
