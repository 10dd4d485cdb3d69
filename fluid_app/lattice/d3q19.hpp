#pragma once
// The D3Q19 velocity set (paper, Sec. LBM; Krueger et al. 2017, Tab. 3.3).
//
// Ordering: 0 is the rest population, 1..9 point "forward" and i + 9 is the opposite of i,
// so opposite(i) is a constant-time expression the compiler folds in unrolled loops.
#include <array>

namespace lbdem::d3q19 {

inline constexpr int Q = 19;
inline constexpr double cs2 = 1.0 / 3.0;  // lattice speed of sound squared

inline constexpr std::array<std::array<int, 3>, Q> c = {{{0, 0, 0},
                                                         {1, 0, 0},
                                                         {0, 1, 0},
                                                         {0, 0, 1},
                                                         {1, 1, 0},
                                                         {1, -1, 0},
                                                         {1, 0, 1},
                                                         {1, 0, -1},
                                                         {0, 1, 1},
                                                         {0, 1, -1},
                                                         {-1, 0, 0},
                                                         {0, -1, 0},
                                                         {0, 0, -1},
                                                         {-1, -1, 0},
                                                         {-1, 1, 0},
                                                         {-1, 0, -1},
                                                         {-1, 0, 1},
                                                         {0, -1, -1},
                                                         {0, -1, 1}}};

inline constexpr std::array<double, Q> w = {
    1.0 / 3.0,  1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0,
    1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 18.0, 1.0 / 18.0, 1.0 / 18.0, 1.0 / 36.0,
    1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0, 1.0 / 36.0};

constexpr int opposite(int i) {
  return i == 0 ? 0 : (i <= 9 ? i + 9 : i - 9);
}

// Second-order equilibrium f_i^eq(rho, u) = w_i rho (1 + 3 c.u + 9/2 (c.u)^2 - 3/2 u^2).
template <class T>
constexpr T equilibrium(int i, T rho, T ux, T uy, T uz) {
  const T cu = T(c[i][0]) * ux + T(c[i][1]) * uy + T(c[i][2]) * uz;
  const T uu = ux * ux + uy * uy + uz * uz;
  return T(w[i]) * rho * (T(1) + T(3) * cu + T(4.5) * cu * cu - T(1.5) * uu);
}

}  // namespace lbdem::d3q19
