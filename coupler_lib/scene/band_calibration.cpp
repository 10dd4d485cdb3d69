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
// differ by at most 0.017 cells (tau 0.505). Measured values and how to rerun them:
// docs/validation.md, section 6 "The calibrated hydrodynamic radius".
constexpr std::array<Point, 17> kNearest{{{0.505, 0.872},
                                          {0.51, 0.778},
                                          {0.52, 0.671},
                                          {0.53, 0.600},
                                          {0.55, 0.503},
                                          {0.575, 0.418},
                                          {0.6, 0.353},
                                          {0.65, 0.254},
                                          {0.7, 0.176},
                                          {0.8, 0.055},
                                          {0.9, -0.044},
                                          {1.0, -0.129},
                                          {1.2, -0.279},
                                          {1.5, -0.475},
                                          {2.0, -0.763},
                                          {2.5, -1.022},
                                          {3.0, -1.258}}};

// The same runs with fluid.porosity_lookup: trilinear (a wider band: 0.007-0.04 cells more).
constexpr std::array<Point, 17> kTrilinear{{{0.505, 0.912},
                                            {0.51, 0.813},
                                            {0.52, 0.700},
                                            {0.53, 0.627},
                                            {0.55, 0.526},
                                            {0.575, 0.438},
                                            {0.6, 0.372},
                                            {0.65, 0.270},
                                            {0.7, 0.192},
                                            {0.8, 0.068},
                                            {0.9, -0.032},
                                            {1.0, -0.118},
                                            {1.2, -0.269},
                                            {1.5, -0.466},
                                            {2.0, -0.755},
                                            {2.5, -1.014},
                                            {3.0, -1.251}}};

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
