#include "fluid_app/analytic/channel_flow.hpp"

#include <cmath>
#include <numbers>

namespace lbdem {

namespace {
// Enough terms that the first dropped one is below 1e-16 of the steady scale (or the sum is
// exhausted by the exponential); capped so a t = 0 call stays cheap.
constexpr int kMaxTerms = 200000;
}  // namespace

double poiseuille_velocity(double y, double height, double accel, double nu, double t) {
  const double pi = std::numbers::pi;
  const double steady = accel * y * (height - y) / (2.0 * nu);
  const double scale = 4.0 * accel * height * height / (nu * pi * pi * pi);
  const double rate = pi * pi * nu * t / (height * height);
  double transient = 0;
  for (int n = 1; n < kMaxTerms; n += 2) {
    const double term = scale / (double(n) * n * n) * std::exp(-double(n) * n * rate);
    transient += term * std::sin(n * pi * y / height);
    if (term < 1e-17 * scale) break;
  }
  return steady - transient;
}

double couette_velocity(double y, double height, double u0, double u1, double nu, double t) {
  const double pi = std::numbers::pi;
  const double steady = u0 + (u1 - u0) * y / height;
  const double rate = pi * pi * nu * t / (height * height);
  const double scale = std::abs(u0) + std::abs(u1);
  double transient = 0;
  for (int n = 1; n < kMaxTerms; ++n) {
    const double sign = n % 2 ? -1.0 : 1.0;
    const double decay = std::exp(-double(n) * n * rate);
    const double term = 2.0 * (u1 * sign - u0) / (n * pi) * decay;
    transient += term * std::sin(n * pi * y / height);
    if (2.0 * scale / (n * pi) * decay < 1e-17 * scale) break;
  }
  return steady + transient;
}

}  // namespace lbdem
