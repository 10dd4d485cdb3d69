#include "coupler_lib/geometry/distance_transform.hpp"

#include <cmath>
#include <limits>

namespace lbdem {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One pass of the squared distance transform along a line of n samples:
// out[q] = min_p (q - p)^2 + f[p], as the lower envelope of the parabolas rooted at the
// finite samples (Felzenszwalb & Huttenlocher 2012, Algorithm 1). Lines without any finite
// sample stay infinite.
void envelope_1d(std::vector<double>& f, std::vector<int>& v, std::vector<double>& z, int n) {
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInf) continue;
    if (k < 0) {
      k = 0;
      v[0] = q;
      z[0] = -kInf;
      z[1] = kInf;
      continue;
    }
    double s;
    while (true) {
      const int p = v[k];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s <= z[k])
        --k;
      else
        break;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  if (k < 0) return;
  std::vector<double> out(n);
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q) ++j;
    const double d = q - v[j];
    out[q] = d * d + f[v[j]];
  }
  f.swap(out);
}

// Squared distance (in voxels) from every voxel to the nearest voxel whose solid flag is
// `feature`.
std::vector<double> squared_edt(const Voxels& vox, std::uint8_t feature) {
  const std::array<int, 3> n = vox.n;
  std::vector<double> d(vox.solid.size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = vox.solid[i] == feature ? 0.0 : kInf;
  const int nmax = std::max({n[0], n[1], n[2]});
  std::vector<double> line(nmax);
  std::vector<int> v(nmax + 1);
  std::vector<double> z(nmax + 2);
  const std::array<std::size_t, 3> stride{1, std::size_t(n[0]), std::size_t(n[0]) * n[1]};
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    for (int j2 = 0; j2 < n[a2]; ++j2)
      for (int j1 = 0; j1 < n[a1]; ++j1) {
        const std::size_t base = j1 * stride[a1] + j2 * stride[a2];
        line.resize(n[axis]);
        for (int q = 0; q < n[axis]; ++q) line[q] = d[base + q * stride[axis]];
        envelope_1d(line, v, z, n[axis]);
        for (int q = 0; q < n[axis]; ++q) d[base + q * stride[axis]] = line[q];
      }
  }
  return d;
}

}  // namespace

std::vector<double> distance_to_other_kind(const Voxels& voxels) {
  const auto to_empty = squared_edt(voxels, 0);
  const auto to_solid = squared_edt(voxels, 1);
  std::vector<double> out(voxels.solid.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = voxels.h * std::sqrt(voxels.solid[i] ? to_empty[i] : to_solid[i]);
  return out;
}

std::vector<double> distance_to_solid(const Voxels& voxels) {
  auto d = squared_edt(voxels, 1);
  for (auto& x : d) x = voxels.h * std::sqrt(x);
  return d;
}

}  // namespace lbdem
