#pragma once
// Fused collide-and-stream D3Q19 kernel with in-place AA-pattern streaming (Bailey et al.,
// "Accelerating lattice Boltzmann fluid flow simulations using graphics processors", 2009).
//
// Storage: structure of arrays, one plane of `stride` values per population, one lattice for
// the whole run. The AA pattern alternates two kinds of step, both in place:
//   even step: read f_i from the cell itself (slot i), collide, write f*_i to slot opp(i)
//              of the same cell;
//   odd step:  read f_i from the neighbour x - c_i, slot opp(i) (where the even step left
//              it), collide, write f*_i to the neighbour x + c_i, slot i.
// After an odd step the lattice holds the natural post-stream populations again. In either
// step every memory location is read and written by the same cell update, so iterations are
// independent (hence `ivdep`) and every written cache line is already in cache: no
// write-allocate traffic. Bytes per cell update: 19 loads + 19 stores,
//   2 * 19 * 8 B = 304 B (double), 2 * 19 * 4 B = 152 B (float),
// plus 4 B porosity + 4 B body index when the porous field is active.
//
// Collision: BGK with Kupershtokh's exact-difference forcing (paper appendix, Eqs.
// forcedShift and physicalVelocity). With v = j / rho the bare velocity,
//   u+ = v + F / rho + (1 - d)(u_p - v),
//   f*_i = f_i - omega (f_i - f_i^eq(rho, v)) + f_i^eq(rho, u+) - f_i^eq(rho, v)
//        = f_i^eq(rho, u+) + (1 - omega)(f_i - f_i^eq(rho, v)).
// One mechanism carries the uniform body force and the HLBM penalization: a porous cell
// only changes u+.
//
// Loads (docs/method-loads.md): the momentum a porous cell gains in the collision is
// rho (u+ - v) = F + pen with pen = rho (1 - d)(u_p - v). The porous rows add, per body, the
// sums of pen, r x pen, (1 - d) rho u+ and (1 - d) r x rho u+ over the cells the body owns
// (PenaltyExchange); the body's force and torque follow from them exactly.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

#include "fluid_app/lattice/d3q19.hpp"
#include "fluid_app/lattice/local_box.hpp"
#include "fluid_app/porous_field.hpp"

namespace lbdem {

// What the kernel computes besides plain BGK (a compile-time choice: a fluid-only scene
// without force runs the plain variant and reads nothing else).
// `porous_one_body` is the kernel's own row variant for rows whose porous cells all belong to
// one body (the common case): the body's parameters are broadcast instead of gathered.
enum class Forcing { none, uniform, porous, porous_one_body };

// Values per body in KernelArgs::exchange: impulse, moment, covered momentum, covered moment.
inline constexpr int kPenaltyTerms = 12;

// Exact (fixed-point) sums of d rho u* and d rho, so that reductions are associative and the
// controller's mean velocity is bit-identical for any rank count.
struct FlowSums {
  std::array<std::int64_t, 3> momentum{};
  std::int64_t mass = 0;
  static constexpr double scale = 1073741824.0;  // 2^30 per lattice unit
};

// An integer of the width of T (the porous row's body slots, see KernelArgs::row_slot).
template <class T>
using SlotInt = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;

template <class T>
struct KernelArgs {
  T* f = nullptr;  // population planes: population i of cell c at f[i * stride + c]
  CellIndex stride = 0;
  LocalBox box;
  T omega = 1;               // 1 / tau
  std::array<T, 3> force{};  // uniform force density, lattice units
  // Porous field (Forcing::porous only). The body table is split into 9 arrays (centre,
  // velocity, angular velocity components: gathers from flat arrays vectorize), each with an
  // entry 0 of zeros for body = -1 and body k at k + 1.
  const float* d = nullptr;
  const std::int32_t* body = nullptr;
  std::array<const T*, 9> table{};
  std::array<T, 9> row_body{};     // porous_one_body: the row's body, same layout as `table`
  std::int32_t row_id = 0;         // porous_one_body: the row's body index + 1
  std::array<T, 3> period{};       // global lattice length on periodic axes
  std::array<T, 3> half_period{};  // period / 2; +infinity on non-periodic axes
  // Per-body exchange sums (porous modes): entry 0 for body -1 (discarded), body k at k + 1,
  // 12 values each in PenaltyExchange order. Added to, in a fixed cell order.
  double* exchange = nullptr;
  // Row scratch, 12 values per cell of the longest row (kPenaltyTerms planes of `row_len`).
  T* scratch = nullptr;
  int row_len = 0;
  // The porous row's d, body index + 1 and node x coordinate (global, g + 1/2), per cell of
  // the row, in the cell loop's own widths: with a float or int32 operand the vectorizer
  // takes twice the cells per iteration, which spills registers and leaves long remainders.
  T* row_d = nullptr;
  SlotInt<T>* row_slot = nullptr;
  T* row_x = nullptr;
};

namespace detail {

// c_i . (x, y, z) over the non-zero components of c_i only: the same value as the three-term
// sum with one to three fewer operations per population. A left-out term is a zero product,
// and adding a zero changes a sum at most in the sign of a zero result, which the equilibrium
// cannot see (it enters as 1 + 3 c.u and (c.u)^2). The compiler may not drop 0 * x itself
// (it is -0 for negative x, NaN for infinite x). Starting from -0 keeps the first term exact.
template <class T>
[[gnu::always_inline]] inline T c_dot(int i, T x, T y, T z) {
  using d3q19::c;
  T s = T(-0.0);
  if (c[i][0] != 0) s += T(c[i][0]) * x;
  if (c[i][1] != 0) s += T(c[i][1]) * y;
  if (c[i][2] != 0) s += T(c[i][2]) * z;
  return s;
}

// a b + c rounded once where the target has a fused multiply-add; elsewhere a b + c, which
// the compiler then cannot contract either (std::fma would be a slow library call there).
template <class T>
[[gnu::always_inline]] inline T fused_mul_add(T a, T b, T c) {
#ifdef __FMA__
  return std::fma(a, b, c);
#else
  return a * b + c;
#endif
}

// Always inlined: the cell loop vectorizes only with the cell's body in it.
template <class T, Forcing Mode, bool Sum>
[[gnu::always_inline]] inline void collide_cell(const KernelArgs<T>& a, int at, int y, int z,
                                                const T (&f)[d3q19::Q], T (&out)[d3q19::Q],
                                                FlowSums& s, T (&ex)[kPenaltyTerms]) {
  using namespace d3q19;
  T rho = 0, jx = 0, jy = 0, jz = 0;
#pragma GCC unroll 19
  for (int i = 0; i < Q; ++i) {
    rho += f[i];
    if (c[i][0] != 0) jx += T(c[i][0]) * f[i];  // zero terms left out, as in c_dot
    if (c[i][1] != 0) jy += T(c[i][1]) * f[i];
    if (c[i][2] != 0) jz += T(c[i][2]) * f[i];
  }
  const T inv_rho = T(1) / rho;
  const T vx = jx * inv_rho, vy = jy * inv_rho, vz = jz * inv_rho;
  T ux = vx, uy = vy, uz = vz;  // u+ (shifted velocity)
  T weight = 1;                 // porosity d, for the flow sums
  if constexpr (Mode != Forcing::none) {
    ux += a.force[0] * inv_rho;
    uy += a.force[1] * inv_rho;
    uz += a.force[2] * inv_rho;
  }
  if constexpr (Mode == Forcing::porous || Mode == Forcing::porous_one_body) {
    const T dd = a.row_d[at];
    T bt[9];
    if constexpr (Mode == Forcing::porous) {
      const SlotInt<T> id = a.row_slot[at];
#pragma GCC unroll 9
      for (int m = 0; m < 9; ++m) bt[m] = a.table[m][id];
    } else {
#pragma GCC unroll 9
      for (int m = 0; m < 9; ++m) bt[m] = a.row_body[m];
    }
    // Node position in global lattice coordinates (node g at g + 1/2), minimum image.
    T r[3] = {a.row_x[at] - bt[0], T(a.box.offset[1] + y - 1) + T(0.5) - bt[1],
              T(a.box.offset[2] + z - 1) + T(0.5) - bt[2]};
    // Centres are wrapped into [0, L) on periodic axes (by the solver), so |r| < L and one
    // conditional shift gives the minimum image (selects vectorize, floor does not).
#pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) {
      r[k] -= r[k] > a.half_period[k] ? a.period[k] : T(0);
      r[k] += r[k] < -a.half_period[k] ? a.period[k] : T(0);
    }
    // u_p = U + Omega x r with each product fused explicitly, in the order the compiler
    // contracts the plain expression on the gather: on the broadcast, where Omega, r_y and r_z
    // are row constants, it would otherwise round some products on their own before the loop
    // (hoisted, unfused), and a covered cell's last bit would depend on which variant its row
    // takes, hence on the rows' split in x.
    const T upx = fused_mul_add(-bt[8], r[1], fused_mul_add(bt[7], r[2], bt[3]));
    const T upy = fused_mul_add(-bt[6], r[2], fused_mul_add(bt[8], r[0], bt[4]));
    const T upz = fused_mul_add(-bt[7], r[0], fused_mul_add(bt[6], r[1], bt[5]));
    const T pen = T(1) - dd;
    ux += pen * (upx - vx);
    uy += pen * (upy - vy);
    uz += pen * (upz - vz);
    weight = dd;
    // Momentum the penalization gives this cell, and the (1 - d) share of its
    // post-collision momentum (the fluid the body covers).
    const T rp = rho * pen;
    const T px = rp * (upx - vx), py = rp * (upy - vy), pz = rp * (upz - vz);
    const T qx = rp * ux, qy = rp * uy, qz = rp * uz;
    ex[0] = px;
    ex[1] = py;
    ex[2] = pz;
    ex[3] = r[1] * pz - r[2] * py;
    ex[4] = r[2] * px - r[0] * pz;
    ex[5] = r[0] * py - r[1] * px;
    ex[6] = qx;
    ex[7] = qy;
    ex[8] = qz;
    ex[9] = r[1] * qz - r[2] * qy;
    ex[10] = r[2] * qx - r[0] * qz;
    ex[11] = r[0] * qy - r[1] * qx;
  }
  if constexpr (Sum) {
    // u* = (v + u+) / 2 (paper, Eq. physicalVelocity).
    const double m = double(weight * rho) * FlowSums::scale;
    s.mass += std::int64_t(m);
    s.momentum[0] += std::int64_t(m * double(T(0.5) * (vx + ux)));
    s.momentum[1] += std::int64_t(m * double(T(0.5) * (vy + uy)));
    s.momentum[2] += std::int64_t(m * double(T(0.5) * (vz + uz)));
  }
  const T keep = T(1) - a.omega;
  const T vv = T(1.5) * (vx * vx + vy * vy + vz * vz);
  if constexpr (Mode == Forcing::none) {
#pragma GCC unroll 19
    for (int i = 0; i < Q; ++i) {
      const T cv = c_dot(i, vx, vy, vz);
      const T feq = T(w[i]) * rho * (T(1) + T(3) * cv + T(4.5) * cv * cv - vv);
      out[i] = feq + keep * (f[i] - feq);
    }
  } else {
    // f*_i = f_i^eq(rho, u+) + keep (f_i - f_i^eq(rho, v)) (Eqs. (1), (2), (5) of
    // docs/method.md) regrouped per cell, so that each population costs a few operations
    // instead of two equilibria:
    //   f*_i = keep f_i + w_i rho [A + 3 c_i.a + 9/2 c_i.M c_i],
    //   a = u+ - keep v,   M = u+ u+^T - keep v v^T,   A = (1 - keep) - 3/2 (u+.u+ - keep v.v).
    // c_i.M c_i is M_kk for an axis direction and M_kk + M_ll +- 2 M_kl for a diagonal one;
    // i and its opposite share it and differ in the sign of c_i.a. Exact algebra, different
    // round-off (docs/performance.md, "The porous kernel").
    const T ax = ux - keep * vx, ay = uy - keep * vy, az = uz - keep * vz;
    const T mxx = ux * ux - keep * (vx * vx), myy = uy * uy - keep * (vy * vy),
            mzz = uz * uz - keep * (vz * vz);
    const T mxy = ux * uy - keep * (vx * vy), mxz = ux * uz - keep * (vx * vz),
            myz = uy * uz - keep * (vy * vz);
    const T A = (T(1) - keep) - T(1.5) * (mxx + myy + mzz);
    out[0] = T(w[0]) * rho * A + keep * f[0];
#pragma GCC unroll 9
    for (int i = 1; i <= 9; ++i) {
      const T ca = c_dot(i, ax, ay, az);
      T q = T(-0.0);  // c_i.M c_i
      if (c[i][0] != 0) q += mxx;
      if (c[i][1] != 0) q += myy;
      if (c[i][2] != 0) q += mzz;
      if (c[i][0] * c[i][1] != 0) q += T(2 * c[i][0] * c[i][1]) * mxy;
      if (c[i][0] * c[i][2] != 0) q += T(2 * c[i][0] * c[i][2]) * mxz;
      if (c[i][1] * c[i][2] != 0) q += T(2 * c[i][1] * c[i][2]) * myz;
      const T b = A + T(4.5) * q;
      const T wr = T(w[i]) * rho;
      out[i] = wr * (b + T(3) * ca) + keep * f[i];
      out[opposite(i)] = wr * (b - T(3) * ca) + keep * f[opposite(i)];
    }
  }
}

}  // namespace detail

namespace detail {

// One row of cells along x: local cells (x0 .. x0+len-1, y, z).
template <class T, bool Odd, Forcing Mode, bool Sum>
inline void collide_row(const KernelArgs<T>& a, int x0, int len, int y, int z, FlowSums& s) {
  using namespace d3q19;
  const CellIndex row = a.box.index(x0, y, z);
  // Per population: where the loads and stores of this row start.
  T* src[Q];
  T* dst[Q];
#pragma GCC unroll 19
  for (int i = 0; i < Q; ++i) {
    const CellIndex sh = a.box.shift(c[i][0], c[i][1], c[i][2]);
    if constexpr (Odd) {
      src[i] = a.f + opposite(i) * a.stride + row - sh;
      dst[i] = a.f + i * a.stride + row + sh;
    } else {
      src[i] = a.f + i * a.stride + row;
      dst[i] = a.f + opposite(i) * a.stride + row;
    }
  }
  constexpr bool porous = Mode == Forcing::porous || Mode == Forcing::porous_one_body;
  std::int64_t m0 = 0, m1 = 0, m2 = 0, mass = 0;
  T* const ex_row = a.scratch;
  const int ex_stride = a.row_len;
#pragma GCC ivdep
  for (int k = 0; k < len; ++k) {
    T fin[Q], fout[Q];
#pragma GCC unroll 19
    for (int i = 0; i < Q; ++i) fin[i] = src[i][k];
    FlowSums cs{};
    T ex[kPenaltyTerms];
    collide_cell<T, Mode, Sum>(a, k, y, z, fin, fout, cs, ex);
    if constexpr (porous) {
#pragma GCC unroll 12
      for (int m = 0; m < kPenaltyTerms; ++m) ex_row[m * ex_stride + k] = ex[m];
    }
    if constexpr (Sum) {
      m0 += cs.momentum[0];
      m1 += cs.momentum[1];
      m2 += cs.momentum[2];
      mass += cs.mass;
    }
#pragma GCC unroll 19
    for (int i = 0; i < Q; ++i) dst[i][k] = fout[i];
  }
  if constexpr (Sum) {
    s.momentum[0] += m0;
    s.momentum[1] += m1;
    s.momentum[2] += m2;
    s.mass += mass;
  }
  // The row's exchange sums, in cell order (reproducible): one add per body and term for a
  // one-body row (cells with d = 1 contribute exact zeros), a scatter by cell otherwise.
  if constexpr (Mode == Forcing::porous_one_body) {
    double* acc = a.exchange + kPenaltyTerms * std::size_t(a.row_id);
    for (int m = 0; m < kPenaltyTerms; ++m) {
      double sum = 0;
      for (int k = 0; k < len; ++k) sum += double(ex_row[m * ex_stride + k]);
      acc[m] += sum;
    }
  } else if constexpr (Mode == Forcing::porous) {
    // Per run of one body's cells (fluid cells between them do not end it), its sums are
    // held in registers: the same additions in the same order as adding cell by cell.
    for (int k = 0; k < len;) {
      if (a.d[row + k] >= 1.0f) {
        ++k;
        continue;
      }
      const std::int32_t b = a.body[row + k];
      double* acc = a.exchange + kPenaltyTerms * std::size_t(b + 1);
      double sum[kPenaltyTerms];
      for (int m = 0; m < kPenaltyTerms; ++m) sum[m] = acc[m];
      for (; k < len; ++k) {
        if (a.d[row + k] >= 1.0f) continue;
        if (a.body[row + k] != b) break;
        for (int m = 0; m < kPenaltyTerms; ++m) sum[m] += double(ex_row[m * ex_stride + k]);
      }
      for (int m = 0; m < kPenaltyTerms; ++m) acc[m] = sum[m];
    }
  }
}

}  // namespace detail

// Whether a row of `len` cells of the porous field takes a porous path in collide_stream: one
// of its cells covered (d < 1). The per-rank counter of the cost model (porous_row_cells) asks
// the same question, so that it counts the rows the kernel runs.
inline bool porous_row(const float* d, int len) {
  int solid = 0;
  for (int k = 0; k < len; ++k) solid += d[k] < 1.0f ? 1 : 0;
  return solid != 0;
}

// Update the cells of `r` (local coordinates, interior only). `Odd` selects the AA step kind.
// With the porous field, a row without any cell of d < 1 takes the uniform-force variant (with
// a zero force if there is none): for d = 1 the shift (1 - d)(u_p - v) adds exactly zero and
// both variants share the regrouped collision, so a fluid cell gets the same bits whichever
// path its row takes (and so for any decomposition), and the cost of bodies grows with the
// rows they touch, not with the domain. (The plain variant, which a run without bodies and
// force takes, rounds differently; splitting porous rows into runs was measured no faster:
// docs/performance.md, "The porous kernel".)
template <class T, bool Odd, Forcing Mode, bool Sum>
void collide_stream(const KernelArgs<T>& args, const CellRange& r, FlowSums& sums) {
  // A private copy: the population stores cannot alias it, so its pointers and constants
  // stay in registers instead of being reloaded after every store (which blocks vectorizing).
  KernelArgs<T> a = args;
  const int len = r.hi[0] - r.lo[0];
  FlowSums s{};
  std::vector<T> scratch;
  std::vector<SlotInt<T>> slots;
  if constexpr (Mode == Forcing::porous) {
    scratch.resize(std::size_t(kPenaltyTerms + 2) * std::size_t(len));
    slots.resize(std::size_t(len));
    a.scratch = scratch.data();
    a.row_len = len;
    a.row_d = a.scratch + std::size_t(kPenaltyTerms) * std::size_t(len);
    a.row_x = a.row_d + len;
    a.row_slot = slots.data();
    for (int k = 0; k < len; ++k) a.row_x[k] = T(a.box.offset[0] + r.lo[0] + k - 1) + T(0.5);
  }
  for (int z = r.lo[2]; z < r.hi[2]; ++z) {
    for (int y = r.lo[1]; y < r.hi[1]; ++y) {
      if constexpr (Mode == Forcing::porous) {
        const CellIndex row = a.box.index(r.lo[0], y, z);
        const float* d = a.d + row;
        if (!porous_row(d, len)) {
          detail::collide_row<T, Odd, Forcing::uniform, Sum>(a, r.lo[0], len, y, z, s);
          continue;
        }
        const std::int32_t* body = a.body + row;
        std::int32_t lo = std::numeric_limits<std::int32_t>::max(), hi = -2;
        for (int k = 0; k < len; ++k) {
          const bool p = d[k] < 1.0f;
          lo = p && body[k] < lo ? body[k] : lo;
          hi = p && body[k] > hi ? body[k] : hi;
          a.row_d[k] = T(d[k]);
          a.row_slot[k] = body[k] + 1;
        }
        if (lo == hi) {
          for (int m = 0; m < 9; ++m) a.row_body[m] = a.table[m][lo + 1];
          a.row_id = lo + 1;
          detail::collide_row<T, Odd, Forcing::porous_one_body, Sum>(a, r.lo[0], len, y, z, s);
          continue;
        }
      }
      detail::collide_row<T, Odd, Mode, Sum>(a, r.lo[0], len, y, z, s);
    }
  }
  if constexpr (Sum) {
    for (int k = 0; k < 3; ++k) sums.momentum[k] += s.momentum[k];
    sums.mass += s.mass;
  }
}

}  // namespace lbdem
