#include "coupler_lib/scene/band_calibration.hpp"

#include <array>
#include <cmath>

namespace lbdem {

namespace {

struct Point {
  double tau;
  double excess;  // (a_h - a) / dx
};

// tools/calibrate_band.py --cells 8 (sphere d = 8 dx in a periodic box of 3 d, phi 0.019,
// Re 0.01), mean of the sphere centred on a node and off it by (0.31, 0.17, 0.43) dx; the two
// differ by 0.03-0.06 cells. Measured values and how to rerun them: docs/validation.md,
// section 6 "The calibrated hydrodynamic radius".
constexpr std::array<Point, 17> kNearest{{{0.505, 0.843},
                                          {0.51, 0.750},
                                          {0.52, 0.653},
                                          {0.53, 0.583},
                                          {0.55, 0.492},
                                          {0.575, 0.410},
                                          {0.6, 0.346},
                                          {0.65, 0.249},
                                          {0.7, 0.173},
                                          {0.8, 0.053},
                                          {0.9, -0.045},
                                          {1.0, -0.130},
                                          {1.2, -0.279},
                                          {1.5, -0.474},
                                          {2.0, -0.761},
                                          {2.5, -1.020},
                                          {3.0, -1.256}}};

// The same runs with fluid.porosity_lookup: trilinear (a wider band: 0.03-0.11 cells more).
constexpr std::array<Point, 17> kTrilinear{{{0.505, 0.959},
                                            {0.51, 0.857},
                                            {0.52, 0.741},
                                            {0.53, 0.665},
                                            {0.55, 0.561},
                                            {0.575, 0.471},
                                            {0.6, 0.402},
                                            {0.65, 0.298},
                                            {0.7, 0.218},
                                            {0.8, 0.092},
                                            {0.9, -0.010},
                                            {1.0, -0.098},
                                            {1.2, -0.251},
                                            {1.5, -0.449},
                                            {2.0, -0.740},
                                            {2.5, -1.001},
                                            {3.0, -1.239}}};

template <std::size_t N>
std::optional<double> interpolate(const std::array<Point, N>& table, double tau) {
  if (!(tau >= table.front().tau && tau <= table.back().tau)) return std::nullopt;
  // The excess is close to linear in ln(tau - 1/2) (the viscosity's logarithm) below tau 1.
  const auto x = [](double t) { return std::log(t - 0.5); };
  for (std::size_t i = 1; i < N; ++i)
    if (tau <= table[i].tau) {
      const double w = (x(tau) - x(table[i - 1].tau)) / (x(table[i].tau) - x(table[i - 1].tau));
      return table[i - 1].excess + w * (table[i].excess - table[i - 1].excess);
    }
  return table.back().excess;
}

}  // namespace

std::optional<double> band_radius_excess_cells(double tau, PorosityLookup lookup) {
  return lookup == PorosityLookup::nearest ? interpolate(kNearest, tau)
                                           : interpolate(kTrilinear, tau);
}

std::string band_calibration_range() {
  return "[0.505, 3]";
}

bool band_calibration_checked(double tau) {
  return tau >= 0.52 && tau <= 1.5;
}

std::string band_calibration_checked_range() {
  return "[0.52, 1.5]";
}

}  // namespace lbdem
