#include <gtest/gtest.h>

#include "fluid_app/lattice/d3q19.hpp"

namespace lbdem {
namespace {

using namespace d3q19;

TEST(D3Q19, WeightsSumToOneAndOppositesPair) {
  double s = 0;
  for (int i = 0; i < Q; ++i) {
    s += w[i];
    for (int k = 0; k < 3; ++k) EXPECT_EQ(c[opposite(i)][k], -c[i][k]) << i;
    EXPECT_EQ(w[opposite(i)], w[i]);
  }
  EXPECT_NEAR(s, 1.0, 1e-15);
}

// Zeroth, first and second moments of f^eq: rho, rho u, rho (cs^2 I + u u).
TEST(D3Q19, EquilibriumMoments) {
  const double rho = 1.07, u[3] = {0.03, -0.05, 0.02};
  double m0 = 0, m1[3] = {0, 0, 0}, m2[3][3] = {};
  for (int i = 0; i < Q; ++i) {
    const double f = equilibrium(i, rho, u[0], u[1], u[2]);
    m0 += f;
    for (int a = 0; a < 3; ++a) {
      m1[a] += c[i][a] * f;
      for (int b = 0; b < 3; ++b) m2[a][b] += c[i][a] * c[i][b] * f;
    }
  }
  EXPECT_NEAR(m0, rho, 1e-14);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(m1[a], rho * u[a], 1e-15);
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(m2[a][b], rho * ((a == b ? cs2 : 0.0) + u[a] * u[b]), 1e-15) << a << b;
  }
}

}  // namespace
}  // namespace lbdem
