#pragma once
// A deliberately plain D3Q19 reference for the tests: two arrays, collide then push-stream,
// boundary rules applied link by link as the textbook writes them. Same collision formula as
// the production kernel (BGK + Kupershtokh shift), none of its storage tricks.
#include <array>
#include <cmath>
#include <vector>

#include "coupler_lib/scene/fluid_section.hpp"
#include "fluid_app/lattice/d3q19.hpp"
#include "fluid_app/porous_field.hpp"

namespace lbdem::testing_fluid {

struct ReferenceLattice {
  std::array<int, 3> n;
  std::array<FaceType, 6> type{};
  std::array<std::array<double, 3>, 6> wall_velocity{};  // lattice units
  std::array<double, 6> wall_density{1, 1, 1, 1, 1, 1};
  double omega = 1;
  std::array<double, 3> force{};
  // Porous field over the whole box (empty: none).
  std::vector<float> d;
  std::vector<int> body;
  std::vector<PorousBody<double>> bodies;
  std::vector<double> f;  // f[cell * 19 + i], cell = x + n0 (y + n1 z), 0-based

  explicit ReferenceLattice(std::array<int, 3> size) : n(size), f(std::size_t(cells()) * 19) {}
  int cells() const { return n[0] * n[1] * n[2]; }
  int id(int x, int y, int z) const { return x + n[0] * (y + n[1] * z); }

  void step() {
    using namespace d3q19;
    std::vector<double> post(f.size()), next(f.size(), 0.0);
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) {
          const int c0 = id(x, y, z);
          double rho = 0, j[3] = {0, 0, 0};
          for (int i = 0; i < Q; ++i) {
            rho += f[c0 * 19 + i];
            for (int k = 0; k < 3; ++k) j[k] += c[i][k] * f[c0 * 19 + i];
          }
          double v[3], u[3];
          for (int k = 0; k < 3; ++k) {
            v[k] = j[k] / rho;
            u[k] = v[k] + force[k] / rho;
          }
          if (!d.empty() && d[c0] < 1.0f) {
            PorousBody<double> b = body[c0] >= 0 ? bodies[body[c0]] : PorousBody<double>{};
            const int g[3] = {x, y, z};
            double r[3];
            for (int k = 0; k < 3; ++k) {
              r[k] = g[k] + 0.5 - b.centre[k];
              if (type[2 * k] == FaceType::periodic) r[k] -= n[k] * std::floor(r[k] / n[k] + 0.5);
            }
            const double up[3] = {b.velocity[0] + b.omega[1] * r[2] - b.omega[2] * r[1],
                                  b.velocity[1] + b.omega[2] * r[0] - b.omega[0] * r[2],
                                  b.velocity[2] + b.omega[0] * r[1] - b.omega[1] * r[0]};
            for (int k = 0; k < 3; ++k) u[k] += (1.0 - d[c0]) * (up[k] - v[k]);
          }
          for (int i = 0; i < Q; ++i) {
            const double fv = equilibrium(i, rho, v[0], v[1], v[2]);
            const double fu = equilibrium(i, rho, u[0], u[1], u[2]);
            post[c0 * 19 + i] = f[c0 * 19 + i] - omega * (f[c0 * 19 + i] - fv) + fu - fv;
          }
        }
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x) {
          const int c0 = id(x, y, z);
          double rho = 0, u[3] = {0, 0, 0};
          for (int i = 0; i < Q; ++i) {
            rho += post[c0 * 19 + i];
            for (int k = 0; k < 3; ++k) u[k] += c[i][k] * post[c0 * 19 + i];
          }
          for (int k = 0; k < 3; ++k) u[k] /= rho;
          for (int i = 0; i < Q; ++i) {
            int t[3] = {x + c[i][0], y + c[i][1], z + c[i][2]};
            int face = -1;
            for (int k = 0; k < 3; ++k) {
              if (t[k] >= 0 && t[k] < n[k]) continue;
              const int fa = 2 * k + (t[k] >= n[k] ? 1 : 0);
              if (type[fa] == FaceType::periodic) {
                t[k] = (t[k] + n[k]) % n[k];
              } else {
                const bool wall = type[fa] != FaceType::pressure;
                if (face < 0 || (wall && type[face] == FaceType::pressure)) face = fa;
              }
            }
            const double out = post[c0 * 19 + i];
            if (face < 0) {
              next[id(t[0], t[1], t[2]) * 19 + i] = out;
              continue;
            }
            double back = out;
            if (type[face] == FaceType::moving_wall) {
              const auto& uw = wall_velocity[face];
              back = out - 6 * w[i] * rho * (c[i][0] * uw[0] + c[i][1] * uw[1] + c[i][2] * uw[2]);
            } else if (type[face] == FaceType::pressure) {
              const double cu = c[i][0] * u[0] + c[i][1] * u[1] + c[i][2] * u[2];
              const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
              back = -out + 2 * w[i] * wall_density[face] * (1 + 4.5 * cu * cu - 1.5 * uu);
            }
            next[c0 * 19 + opposite(i)] = back;
          }
        }
    f.swap(next);
  }
};

}  // namespace lbdem::testing_fluid
