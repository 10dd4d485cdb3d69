#include "fluid_app/hlbm/reference_porosity.hpp"

#include "fluid_app/lattice/d3q19.hpp"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace lbdem::hlbm {

ReferencePorosity::ReferencePorosity(const Voxels& voxels) : h_(voxels.h) {
  const auto& n = voxels.n;
  if (!(h_ > 0) || n[0] < 1 || n[1] < 1 || n[2] < 1 ||
      voxels.fill.size() != static_cast<std::size_t>(n[0]) * n[1] * n[2])
    throw std::invalid_argument(
        "reference porosity: empty or inconsistent voxel lattice (h=" + std::to_string(h_) + ")");
  for (int a = 0; a < 3; ++a) m_[a] = n[a] + 2 * kPad;
  shift_ = -voxels.origin / h_ + Eigen::Vector3d::Constant(kPad);

  // Fluid fraction of a voxel: 1 - fill, 1 off the lattice.
  auto fluid_at = [&](int i, int j, int k) {
    if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) return 1.0f;
    return 1.0f -
           voxels.fill[static_cast<std::size_t>(i) +
                       static_cast<std::size_t>(n[0]) *
                           (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1]) * k)];
  };

  smooth_.assign(static_cast<std::size_t>(m_[0]) * m_[1] * m_[2], 1.0f);
  fluid_.assign(smooth_.size(), 1.0f);
  std::size_t idx = 0;
  for (int k = 0; k < m_[2]; ++k)
    for (int j = 0; j < m_[1]; ++j)
      for (int i = 0; i < m_[0]; ++i, ++idx) {
        fluid_[idx] = fluid_at(i - kPad, j - kPad, k - kPad);
        double fluid = 0;
        for (const auto& c : d3q19::c)
          fluid += fluid_at(i - kPad + c[0], j - kPad + c[1], k - kPad + c[2]);
        // fluid / 19 is exactly 1 (or 0) when all 19 points are wholly fluid (or solid).
        smooth_[idx] = static_cast<float>(fluid / 19.0);
      }

  // Block classes: running minimum and maximum of the fluid fraction over 5 voxels along each
  // axis in turn (outside the padded lattice: 1).
  std::vector<float> lo = fluid_, hi = fluid_;
  const std::array<std::size_t, 3> stride = {1, static_cast<std::size_t>(m_[0]),
                                             static_cast<std::size_t>(m_[0]) * m_[1]};
  for (int a = 0; a < 3; ++a) {
    const std::vector<float> lo0 = lo, hi0 = hi;
    idx = 0;
    for (int k = 0; k < m_[2]; ++k)
      for (int j = 0; j < m_[1]; ++j)
        for (int i = 0; i < m_[0]; ++i, ++idx) {
          const int l = a == 0 ? i : a == 1 ? j : k;
          for (int s = -2; s <= 2; ++s) {
            if (l + s < 0 || l + s >= m_[a]) {
              hi[idx] = std::max(hi[idx], 1.0f);
              continue;
            }
            const std::size_t o = static_cast<std::size_t>(
                static_cast<std::ptrdiff_t>(idx) + s * static_cast<std::ptrdiff_t>(stride[a]));
            lo[idx] = std::min(lo[idx], lo0[o]);
            hi[idx] = std::max(hi[idx], hi0[o]);
          }
        }
  }
  block_.resize(fluid_.size());
  for (std::size_t v = 0; v < fluid_.size(); ++v)
    block_[v] = lo[v] == 1.0f ? Block::fluid : hi[v] == 0.0f ? Block::solid : Block::mixed;

  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        if (fluid_at(i, j, k) == 1.0f) continue;
        const double r = (voxels.origin + h_ * Eigen::Vector3d(i, j, k)).norm();
        // The smoothed porosity is < 1 up to sqrt(2) h (edge stencil point) plus sqrt(3) h
        // (trilinear cell) from a solid voxel centre; 2 sqrt(3) h bounds both.
        support_radius_ = std::max(support_radius_, r + 2.0 * std::sqrt(3.0) * h_);
        surface_radius_ = std::max(surface_radius_, r + 0.5 * std::sqrt(3.0) * h_);
      }
}

double ReferencePorosity::read_points(const Eigen::Vector3d& ref,
                                      const NearestStencil& stencil) const {
  const std::size_t sy = static_cast<std::size_t>(m_[0]);
  const std::size_t sz = sy * static_cast<std::size_t>(m_[1]);
  // Voxel index of every point, four at a time where AVX2 is there (the same additions and
  // comparisons as the scalar loop); a point off the lattice reads voxel 0, a fluid voxel of the
  // padding.
  alignas(32) std::array<std::int32_t, NearestStencil::kPadded> voxel;
  const auto iy = static_cast<std::int32_t>(sy), iz = static_cast<std::int32_t>(sz);
#if defined(__AVX2__)
  {
    const __m256d half = _mm256_set1_pd(kNearestHalf), zero = _mm256_setzero_pd();
    const __m256d rx = _mm256_set1_pd(ref.x()), ry = _mm256_set1_pd(ref.y()),
                  rz = _mm256_set1_pd(ref.z());
    const __m256d mx = _mm256_set1_pd(m_[0]), my = _mm256_set1_pd(m_[1]),
                  mz = _mm256_set1_pd(m_[2]);
    const __m128i vy = _mm_set1_epi32(iy), vz = _mm_set1_epi32(iz);
    for (int g = 0; g < NearestStencil::kPadded; g += 4) {
      const __m256d x = _mm256_add_pd(_mm256_add_pd(rx, _mm256_load_pd(&stencil.x[g])), half);
      const __m256d y = _mm256_add_pd(_mm256_add_pd(ry, _mm256_load_pd(&stencil.y[g])), half);
      const __m256d z = _mm256_add_pd(_mm256_add_pd(rz, _mm256_load_pd(&stencil.z[g])), half);
      const __m256d on = _mm256_and_pd(
          _mm256_and_pd(
              _mm256_and_pd(_mm256_cmp_pd(x, zero, _CMP_GE_OQ), _mm256_cmp_pd(x, mx, _CMP_LT_OQ)),
              _mm256_and_pd(_mm256_cmp_pd(y, zero, _CMP_GE_OQ), _mm256_cmp_pd(y, my, _CMP_LT_OQ))),
          _mm256_and_pd(_mm256_cmp_pd(z, zero, _CMP_GE_OQ), _mm256_cmp_pd(z, mz, _CMP_LT_OQ)));
      const __m128i i = _mm256_cvttpd_epi32(_mm256_and_pd(x, on));
      const __m128i j = _mm256_cvttpd_epi32(_mm256_and_pd(y, on));
      const __m128i k = _mm256_cvttpd_epi32(_mm256_and_pd(z, on));
      const __m128i v =
          _mm_add_epi32(_mm_add_epi32(i, _mm_mullo_epi32(j, vy)), _mm_mullo_epi32(k, vz));
      _mm_store_si128(reinterpret_cast<__m128i*>(&voxel[static_cast<std::size_t>(g)]), v);
    }
  }
#else
  for (std::size_t i = 0; i < NearestStencil::kPadded; ++i) {
    const double x = ref.x() + stencil.x[i] + kNearestHalf;
    const double y = ref.y() + stencil.y[i] + kNearestHalf;
    const double z = ref.z() + stencil.z[i] + kNearestHalf;
    const bool on = x >= 0 && y >= 0 && z >= 0 && x < m_[0] && y < m_[1] && z < m_[2];
    voxel[i] = on ? static_cast<std::int32_t>(x) + iy * static_cast<std::int32_t>(y) +
                        iz * static_cast<std::int32_t>(z)
                  : 0;
  }
#endif
  // Summed in stencil order: the same bits as the point-by-point sum.
  float fluid = 0;
  for (int i = 0; i < NearestStencil::kPoints; ++i)
    fluid += fluid_[static_cast<std::size_t>(voxel[static_cast<std::size_t>(i)])];
  return fluid / 19.0f;  // as the averaged lattice: exactly 0 or 1 at the ends
}

}  // namespace lbdem::hlbm
