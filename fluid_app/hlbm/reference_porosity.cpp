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

ReferencePorosity::ReferencePorosity(const Voxels& voxels, int step)
    : h_(voxels.h), step_(step), pad_(step + 1) {
  const auto& n = voxels.n;
  if (!(h_ > 0) || step < 1 || n[0] < 1 || n[1] < 1 || n[2] < 1 ||
      voxels.fill.size() != static_cast<std::size_t>(n[0]) * n[1] * n[2])
    throw std::invalid_argument("reference porosity: empty or inconsistent voxel lattice (h=" +
                                std::to_string(h_) + ", step " + std::to_string(step) + ")");
  const double reach = step * std::sqrt(2.0) + 1e-9;  // the stencil's extent, voxels
  point_pad_ = static_cast<int>(std::ceil(reach));
  box_ = static_cast<int>(std::ceil(2 * reach)) + 1;
  for (int a = 0; a < 3; ++a) m_[a] = n[a] + 2 * pad_;
  shift_ = -voxels.origin / h_ + Eigen::Vector3d::Constant(pad_);

  // Fluid fraction of a voxel: 1 - fill, 1 off the lattice.
  auto fluid_at = [&](int i, int j, int k) {
    if (i < 0 || j < 0 || k < 0 || i >= n[0] || j >= n[1] || k >= n[2]) return 1.0f;
    return 1.0f -
           voxels.fill[static_cast<std::size_t>(i) +
                       static_cast<std::size_t>(n[0]) *
                           (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1]) * k)];
  };

  smooth_.assign(static_cast<std::size_t>(m_[0]) * m_[1] * m_[2], 1.0f);
  std::vector<float> fluid(smooth_.size(), 1.0f);  // on the padded lattice
  std::size_t idx = 0;
  for (int k = 0; k < m_[2]; ++k)
    for (int j = 0; j < m_[1]; ++j)
      for (int i = 0; i < m_[0]; ++i, ++idx) {
        fluid[idx] = fluid_at(i - pad_, j - pad_, k - pad_);
        double sum = 0;
        for (const auto& c : d3q19::c)
          sum += fluid_at(i - pad_ + step * c[0], j - pad_ + step * c[1], k - pad_ + step * c[2]);
        // sum / 19 is exactly 1 (or 0) when all 19 points are wholly fluid (or solid).
        smooth_[idx] = static_cast<float>(sum / 19.0);
      }

  const std::array<std::ptrdiff_t, 3> e = {m_[0] + 2 * point_pad_, m_[1] + 2 * point_pad_,
                                           m_[2] + 2 * point_pad_};
  stride_ = {e[0], e[0] * e[1]};
  fluid_origin_ = point_pad_ * (1 + stride_[0] + stride_[1]);
  fluid_.assign(static_cast<std::size_t>(e[0] * e[1] * e[2]), 1.0f);
  idx = 0;
  for (int k = 0; k < m_[2]; ++k)
    for (int j = 0; j < m_[1]; ++j)
      for (int i = 0; i < m_[0]; ++i, ++idx)
        fluid_[static_cast<std::size_t>(fluid_origin_ + i + stride_[0] * j + stride_[1] * k)] =
            fluid[idx];

  // Boxes: running minimum and maximum over voxels l .. l + box_ - 1 along each axis in turn,
  // on the lattice of box origins l = -point_pad_ .. m - 1 (voxels beyond the padded lattice:
  // fluid).
  const std::array<int, 3> q = {m_[0] + point_pad_, m_[1] + point_pad_, m_[2] + point_pad_};
  block_stride_ = {static_cast<std::size_t>(q[0]), static_cast<std::size_t>(q[0]) * q[1]};
  const std::size_t boxes = block_stride_[1] * static_cast<std::size_t>(q[2]);
  auto fluid_or_one = [&](int i, int j, int k) {
    if (i < -point_pad_ || j < -point_pad_ || k < -point_pad_ || i >= m_[0] + point_pad_ ||
        j >= m_[1] + point_pad_ || k >= m_[2] + point_pad_)
      return 1.0f;
    return fluid_[static_cast<std::size_t>(fluid_origin_ + i + stride_[0] * j + stride_[1] * k)];
  };
  std::vector<float> lo(boxes), hi(boxes);
  idx = 0;
  for (int k = 0; k < q[2]; ++k)
    for (int j = 0; j < q[1]; ++j)
      for (int i = 0; i < q[0]; ++i, ++idx) {
        float l = 1.0f, u = 0.0f;
        for (int s = 0; s < box_; ++s) {
          const float v = fluid_or_one(i - point_pad_ + s, j - point_pad_, k - point_pad_);
          l = std::min(l, v);
          u = std::max(u, v);
        }
        lo[idx] = l;
        hi[idx] = u;
      }
  // Along y and z the values beyond the box lattice are those of voxels beyond the padded
  // lattice plus one: fluid.
  for (int a = 1; a < 3; ++a) {
    const std::vector<float> l0 = lo, h0 = hi;
    idx = 0;
    for (int k = 0; k < q[2]; ++k)
      for (int j = 0; j < q[1]; ++j)
        for (int i = 0; i < q[0]; ++i, ++idx)
          for (int s = 1; s < box_; ++s) {
            const int l = (a == 1 ? j : k) + s;
            if (l >= q[a]) {
              hi[idx] = std::max(hi[idx], 1.0f);
              continue;
            }
            const std::size_t o = idx + static_cast<std::size_t>(s) * block_stride_[a - 1];
            lo[idx] = std::min(lo[idx], l0[o]);
            hi[idx] = std::max(hi[idx], h0[o]);
          }
  }
  blocks_.resize(boxes + 3);  // three bytes more: the batched lookup reads four at a box's byte
  for (std::size_t v = 0; v < boxes; ++v)
    blocks_[v] = lo[v] == 1.0f ? Block::fluid : hi[v] == 0.0f ? Block::solid : Block::mixed;

  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        if (fluid_at(i, j, k) == 1.0f) continue;
        const double r = (voxels.origin + h_ * Eigen::Vector3d(i, j, k)).norm();
        // The smoothed porosity is < 1 up to step sqrt(2) h (edge stencil point) plus sqrt(3) h
        // (trilinear cell) from a solid voxel centre; (step + 1) sqrt(3) h bounds both.
        support_radius_ = std::max(support_radius_, r + (step + 1) * std::sqrt(3.0) * h_);
        surface_radius_ = std::max(surface_radius_, r + 0.5 * std::sqrt(3.0) * h_);
      }
}

// Each point reads the voxel floor(p + o_i + kNearestHalf), the coordinate rounded as
// (p + o_i) + kNearestHalf; the values are summed in stencil order. The node's nearest voxel lies
// on the padded lattice (its box is mixed), so every point's voxel lies on fluid_, whose layers
// beyond the padded lattice are fluid like every point off it.
float ReferencePorosity::read_points(double x, double y, double z,
                                     const NearestStencil& stencil) const {
  const float* base = fluid_.data() + fluid_origin_;
  float fluid = 0;
  for (std::size_t i = 0; i < NearestStencil::kPoints; ++i) {
    const double px = std::floor((x + stencil.x[i]) + kNearestHalf);
    const double py = std::floor((y + stencil.y[i]) + kNearestHalf);
    const double pz = std::floor((z + stencil.z[i]) + kNearestHalf);
    fluid += base[static_cast<std::ptrdiff_t>(px) + stride_[0] * static_cast<std::ptrdiff_t>(py) +
                  stride_[1] * static_cast<std::ptrdiff_t>(pz)];
  }
  return fluid / 19.0f;  // as the averaged lattice: exactly 0 or 1 at the ends
}

// The class of the box every node's points can reach (four nodes at a time where AVX2 is
// there, the same additions, comparisons, floors and truncations as box_at), then the 19 points
// of the mixed ones.
void ReferencePorosity::nearest(NearestBatch& batch, const NearestStencil& stencil) const {
  const std::size_t n = batch.count;
  std::size_t count = 0, k = 0;
#if defined(__AVX2__)
  const __m256d half = _mm256_set1_pd(kNearestHalf), zero = _mm256_setzero_pd();
  const __m256d pad = _mm256_set1_pd(point_pad_);
  const __m256d ex = _mm256_set1_pd(stencil.extent[0]), ey = _mm256_set1_pd(stencil.extent[1]),
                ez = _mm256_set1_pd(stencil.extent[2]);
  const __m256d mx = _mm256_set1_pd(m_[0]), my = _mm256_set1_pd(m_[1]), mz = _mm256_set1_pd(m_[2]);
  const __m128i sy = _mm_set1_epi32(static_cast<int>(block_stride_[0]));
  const __m128i sz = _mm_set1_epi32(static_cast<int>(block_stride_[1]));
  const __m128i byte = _mm_set1_epi32(0xff), fluid = _mm_set1_epi32(int(Block::fluid));
  const __m128i mixed = _mm_set1_epi32(int(Block::mixed)), lanes = _mm_setr_epi32(1, 2, 4, 8);
  const auto* boxes = reinterpret_cast<const int*>(blocks_.data());
  for (; k + 4 <= n; k += 4) {
    const __m256d x = _mm256_add_pd(_mm256_loadu_pd(&batch.x[k]), half);
    const __m256d y = _mm256_add_pd(_mm256_loadu_pd(&batch.y[k]), half);
    const __m256d z = _mm256_add_pd(_mm256_loadu_pd(&batch.z[k]), half);
    const __m256d on = _mm256_and_pd(
        _mm256_and_pd(
            _mm256_and_pd(_mm256_cmp_pd(x, zero, _CMP_GE_OQ), _mm256_cmp_pd(x, mx, _CMP_LT_OQ)),
            _mm256_and_pd(_mm256_cmp_pd(y, zero, _CMP_GE_OQ), _mm256_cmp_pd(y, my, _CMP_LT_OQ))),
        _mm256_and_pd(_mm256_cmp_pd(z, zero, _CMP_GE_OQ), _mm256_cmp_pd(z, mz, _CMP_LT_OQ)));
    // Box origins floor(x - e) + point_pad_ >= 0 on the padded lattice; lanes off it read box 0.
    auto origin = [&](__m256d v, __m256d e) {
      return _mm256_cvttpd_epi32(
          _mm256_and_pd(_mm256_add_pd(_mm256_floor_pd(_mm256_sub_pd(v, e)), pad), on));
    };
    const __m128i i = origin(x, ex), j = origin(y, ey), l = origin(z, ez);
    const __m128i box =
        _mm_add_epi32(_mm_add_epi32(i, _mm_mullo_epi32(j, sy)), _mm_mullo_epi32(l, sz));
    // Four bytes read at each box's byte (blocks_ is padded), the first kept; off the padded
    // lattice: fluid.
    const __m128i read = _mm_and_si128(
        _mm_mask_i32gather_epi32(_mm_setzero_si128(), boxes, box, _mm_set1_epi32(-1), 1), byte);
    const __m128i on_bits = _mm_set1_epi32(_mm256_movemask_pd(on));
    const __m128i inside = _mm_cmpeq_epi32(_mm_and_si128(on_bits, lanes), lanes);  // -1 or 0
    const __m128i cls = _mm_blendv_epi8(fluid, read, inside);
    _mm_storeu_ps(&batch.d[k],
                  _mm_castsi128_ps(_mm_and_si128(_mm_cmpeq_epi32(cls, fluid),
                                                 _mm_castps_si128(_mm_set1_ps(1.0f)))));
    const int m = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(cls, mixed)));
    for (int lane = 0; lane < 4; ++lane) {
      batch.mixed[count] = static_cast<std::uint32_t>(k) + static_cast<std::uint32_t>(lane);
      count += static_cast<std::size_t>((m >> lane) & 1);
    }
  }
#endif
  for (; k < n; ++k) {
    const Block b = box_at(batch.x[k] + kNearestHalf, batch.y[k] + kNearestHalf,
                           batch.z[k] + kNearestHalf, stencil);
    batch.d[k] = b == Block::fluid ? 1.0f : 0.0f;
    batch.mixed[count] = static_cast<std::uint32_t>(k);
    count += b == Block::mixed;
  }
  batch.mixed_count = count;
  read_points(batch, stencil);
}

void NearestStencil::set_extent() {
  for (int a = 0; a < 3; ++a) {
    const std::array<double, kPadded>& o = a == 0 ? x : a == 1 ? y : z;
    double e = 0;
    for (int i = 0; i < kPoints; ++i) e = std::max(e, std::abs(o[static_cast<std::size_t>(i)]));
    extent[static_cast<std::size_t>(a)] = e + 1e-9;
  }
}

// Four nodes per vector, the lanes doing the scalar read_points' operations in its order: the
// additions and the floor are exact IEEE operations, the voxel index is an exact integer in
// double, and each lane sums its own 19 values in stencil order.
void ReferencePorosity::read_points(NearestBatch& batch, const NearestStencil& stencil) const {
  const std::span<const std::uint32_t> mixed = batch.mixed_nodes();
  std::size_t k = 0;
#if defined(__AVX2__)
  const float* base = fluid_.data() + fluid_origin_;
  const __m256d half = _mm256_set1_pd(kNearestHalf), zero = _mm256_setzero_pd();
  const __m256d all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const __m128 ones = _mm_castsi128_ps(_mm_set1_epi32(-1));
  const __m256d sy = _mm256_set1_pd(static_cast<double>(stride_[0]));
  const __m256d sz = _mm256_set1_pd(static_cast<double>(stride_[1]));
  // The voxels of the 19 points of four nodes.
  auto voxels = [&](std::size_t first, __m128i* voxel) {
    const __m128i node = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&mixed[first]));
    // Masked gathers with a defined source: the plain ones read an undefined register, which
    // GCC reports as maybe-uninitialized.
    const __m256d x = _mm256_mask_i32gather_pd(zero, batch.x.data(), node, all, 8);
    const __m256d y = _mm256_mask_i32gather_pd(zero, batch.y.data(), node, all, 8);
    const __m256d z = _mm256_mask_i32gather_pd(zero, batch.z.data(), node, all, 8);
    for (std::size_t i = 0; i < NearestStencil::kPoints; ++i) {
      const __m256d px =
          _mm256_floor_pd(_mm256_add_pd(_mm256_add_pd(x, _mm256_set1_pd(stencil.x[i])), half));
      const __m256d py =
          _mm256_floor_pd(_mm256_add_pd(_mm256_add_pd(y, _mm256_set1_pd(stencil.y[i])), half));
      const __m256d pz =
          _mm256_floor_pd(_mm256_add_pd(_mm256_add_pd(z, _mm256_set1_pd(stencil.z[i])), half));
      voxel[i] = _mm256_cvtpd_epi32(_mm256_fmadd_pd(pz, sz, _mm256_fmadd_pd(py, sy, px)));
    }
  };
  auto store = [&](std::size_t first, __m128 fluid) {
    alignas(16) std::array<float, 4> d;
    _mm_store_ps(d.data(), _mm_div_ps(fluid, _mm_set1_ps(19.0f)));
    for (std::size_t l = 0; l < 4; ++l) batch.d[mixed[first + l]] = d[l];
  };
  // Eight nodes per round, two independent sums, the indices computed before the loads.
  __m128i va[NearestStencil::kPoints], vb[NearestStencil::kPoints];
  for (; k + 8 <= mixed.size(); k += 8) {
    voxels(k, va);
    voxels(k + 4, vb);
    __m128 fa = _mm_setzero_ps(), fb = _mm_setzero_ps();
    for (std::size_t i = 0; i < NearestStencil::kPoints; ++i) {
      fa = _mm_add_ps(fa, _mm_mask_i32gather_ps(_mm_setzero_ps(), base, va[i], ones, 4));
      fb = _mm_add_ps(fb, _mm_mask_i32gather_ps(_mm_setzero_ps(), base, vb[i], ones, 4));
    }
    store(k, fa);
    store(k + 4, fb);
  }
#endif
  for (; k < mixed.size(); ++k) {
    const std::uint32_t node = mixed[k];
    batch.d[node] = read_points(batch.x[node], batch.y[node], batch.z[node], stencil);
  }
}

}  // namespace lbdem::hlbm
