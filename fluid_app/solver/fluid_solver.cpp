#include "fluid_app/solver/fluid_solver.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <stdexcept>

#include "fluid_app/boundary/boundary_links.hpp"
#include "fluid_app/kernel/aa_kernel.hpp"
#include "fluid_app/lattice/d3q19.hpp"
#include "fluid_app/parallel/halo_exchange.hpp"

namespace lbdem {

namespace {

// 64-byte aligned storage for the population planes (full vector loads, no split lines).
template <class T>
struct AlignedArray {
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T[], Free> data;
  explicit AlignedArray(CellIndex n) {
    const std::size_t bytes = ((std::size_t(n) * sizeof(T) + 63) / 64) * 64;
    data.reset(static_cast<T*>(std::aligned_alloc(64, bytes)));
    if (!data) throw std::bad_alloc();
  }
};

std::array<FaceRule, 6> face_rules(const FluidParams& p) {
  std::array<FaceRule, 6> r{};
  for (int f = 0; f < 6; ++f) {
    r[f].type = int(p.faces[f].type);
    for (int a = 0; a < 3; ++a) r[f].velocity[a] = p.faces[f].velocity[a] / p.units.velocity();
    // p = c_s^2 (rho - 1) in lattice units.
    r[f].density = 1.0 + 3.0 * p.faces[f].pressure / p.units.pressure();
  }
  return r;
}

template <class T, bool Odd, Forcing M>
void run_kernel(bool sum, const KernelArgs<T>& a, const CellRange& r, FlowSums& s) {
  if (sum)
    collide_stream<T, Odd, M, true>(a, r, s);
  else
    collide_stream<T, Odd, M, false>(a, r, s);
}

template <class T, bool Odd>
void run_kernel(Forcing m, bool sum, const KernelArgs<T>& a, const CellRange& r, FlowSums& s) {
  switch (m) {
    case Forcing::none:
      run_kernel<T, Odd, Forcing::none>(sum, a, r, s);
      break;
    case Forcing::uniform:
      run_kernel<T, Odd, Forcing::uniform>(sum, a, r, s);
      break;
    case Forcing::porous:
    case Forcing::porous_one_body:  // a row-level choice the porous kernel makes itself
      run_kernel<T, Odd, Forcing::porous>(sum, a, r, s);
      break;
  }
}

}  // namespace

template <class T>
class FluidSolverImpl {
 public:
  FluidSolverImpl(const FluidParams& p, MPI_Comm comm, std::array<int, 3> dims,
                  const std::array<std::vector<double>, 3>& weights)
      : params(p),
        dec(comm, p.cells, {p.periodic(0), p.periodic(1), p.periodic(2)}, dims, weights),
        box(dec.box()),
        stride(pad(box.cells_with_ghosts())),
        f(stride * d3q19::Q),
        halo(dec, stride),
        bnd(dec, face_rules(p), stride) {
    using namespace d3q19;
    for (CellIndex c = 0; c < box.cells_with_ghosts(); ++c)
      for (int i = 0; i < Q; ++i) f.data[i * stride + c] = T(w[i]);
    for (CellIndex c = box.cells_with_ghosts(); c < stride; ++c)
      for (int i = 0; i < Q; ++i) f.data[i * stride + c] = T(0);
    for (int a = 0; a < 3; ++a) force[a] = p.body_force[a] / p.units.acceleration();
    nodes = double(box.global[0]) * double(box.global[1]) * double(box.global[2]);
    split_core_shell();
  }

  // Planes are padded to whole cache lines plus one line, so that the 19 planes of a large
  // power-of-two lattice do not map onto the same cache sets.
  static CellIndex pad(CellIndex n) {
    const CellIndex line = 64 / sizeof(T);
    return (n + line - 1) / line * line + line;
  }

  // Inner cells (a margin of one cell on axes split over several ranks) are updated while
  // the halo messages are in flight; the shell feeds the messages and goes first.
  void split_core_shell() {
    CellRange all{{1, 1, 1}, {box.n[0] + 1, box.n[1] + 1, box.n[2] + 1}};
    core = all;
    for (int a = 0; a < 3; ++a)
      if (dec.dims()[a] > 1) {
        core.lo[a] = 2;
        core.hi[a] = box.n[a];
      }
    if (core.empty()) {
      shell = {all};
      core = CellRange{};
      return;
    }
    // Peel the slabs outside the core: z first (whole planes), then y, then x.
    CellRange rest = all;
    for (int a = 2; a >= 0; --a) {
      if (core.lo[a] > rest.lo[a]) {
        CellRange s = rest;
        s.hi[a] = core.lo[a];
        shell.push_back(s);
      }
      if (core.hi[a] < rest.hi[a]) {
        CellRange s = rest;
        s.lo[a] = core.hi[a];
        shell.push_back(s);
      }
      rest.lo[a] = core.lo[a];
      rest.hi[a] = core.hi[a];
    }
  }

  bool swapped() const { return steps % 2 == 1; }

  T population(int i, CellIndex cell) const {
    using namespace d3q19;
    if (swapped())
      return f.data[opposite(i) * stride + cell - box.shift(c[i][0], c[i][1], c[i][2])];
    return f.data[i * stride + cell];
  }

  T& population_ref(int i, CellIndex cell) {
    using namespace d3q19;
    if (swapped())
      return f.data[opposite(i) * stride + cell - box.shift(c[i][0], c[i][1], c[i][2])];
    return f.data[i * stride + cell];
  }

  void step() {
    const bool odd = swapped();
    KernelArgs<T> a;
    a.f = f.data.get();
    a.stride = stride;
    a.box = box;
    a.omega = T(1.0 / params.tau);
    for (int k = 0; k < 3; ++k) a.force[k] = T(force[k]);
    Forcing mode =
        (force[0] != 0 || force[1] != 0 || force[2] != 0) ? Forcing::uniform : Forcing::none;
    if (porous_field.active) {
      mode = Forcing::porous;
      a.d = porous_field.d.data();
      a.body = porous_field.body.data();
      for (int m = 0; m < 9; ++m) a.table[m] = porous_field.bodies.column(m);
      exchange.assign(std::size_t(kPenaltyTerms) * (porous_field.bodies.size() + 1), 0.0);
      a.exchange = exchange.data();
      for (int k = 0; k < 3; ++k) {
        a.period[k] = dec.periodic(k) ? T(box.global[k]) : T(0);
        a.half_period[k] =
            dec.periodic(k) ? T(0.5) * T(box.global[k]) : std::numeric_limits<T>::infinity();
      }
    }
    const bool sum = measure;
    FlowSums sums;
    auto run = [&](const CellRange& r) {
      if (r.empty()) return;
      if (odd)
        run_kernel<T, true>(mode, sum, a, r, sums);
      else
        run_kernel<T, false>(mode, sum, a, r, sums);
    };
    for (const CellRange& r : shell) run(r);
    halo.start(f.data.get(), odd);
    run(core);
    halo.finish(f.data.get(), odd);
    bnd.apply(f.data.get(), odd);
    ++steps;
    if (porous_field.active) store_exchange();
    for (int k = 0; k < 3; ++k) impulse[k] += force[k] * double(nodes);
    if (sum) reduce_flow(sums);
  }

  // Cells of the rows of the shell and the core that the kernel runs on a porous path now.
  double porous_row_cells() const {
    if (!porous_field.active) return 0;
    double cells = 0;
    auto count = [&](const CellRange& r) {
      if (r.empty()) return;
      const int len = r.hi[0] - r.lo[0];
      for (int z = r.lo[2]; z < r.hi[2]; ++z)
        for (int y = r.lo[1]; y < r.hi[1]; ++y)
          if (porous_row(porous_field.d.data() + box.index(r.lo[0], y, z), len)) cells += len;
    };
    for (const CellRange& r : shell) count(r);
    count(core);
    return cells;
  }

  // The kernel's flat sums (entry 0: body -1) as one PenaltyExchange per body.
  void store_exchange() {
    auto& out = porous_field.exchange;
    out.resize(porous_field.bodies.size());
    for (std::size_t k = 0; k < out.size(); ++k) {
      const double* e = exchange.data() + kPenaltyTerms * (k + 1);
      for (int m = 0; m < 3; ++m) {
        out[k].impulse[m] = e[m];
        out[k].moment[m] = e[3 + m];
        out[k].covered[m] = e[6 + m];
        out[k].covered_moment[m] = e[9 + m];
      }
    }
  }

  void reduce_flow(const FlowSums& s) {
    std::int64_t local[4] = {s.momentum[0], s.momentum[1], s.momentum[2], s.mass};
    std::int64_t global[4];
    MPI_Allreduce(local, global, 4, MPI_INT64_T, MPI_SUM, dec.comm());
    mean.mass = double(global[3]) / FlowSums::scale;
    for (int k = 0; k < 3; ++k)
      mean.velocity[k] = global[3] > 0 ? double(global[k]) / double(global[3]) : 0.0;
  }

  PorousField<T>& porous() {
    if (porous_field.d.empty()) {
      porous_field.d.assign(std::size_t(box.cells_with_ghosts()), 1.0f);
      porous_field.body.assign(std::size_t(box.cells_with_ghosts()), -1);
    }
    return porous_field;
  }

  FluidParams params;
  Decomposition dec;
  LocalBox box;
  CellIndex stride;
  AlignedArray<T> f;
  HaloExchange<T> halo;
  BoundaryLinks<T> bnd;
  CellRange core;
  std::vector<CellRange> shell;
  std::int64_t steps = 0;
  std::array<double, 3> force{};    // the uniform force of the next step
  std::array<double, 3> impulse{};  // sum over steps of force * nodes
  double nodes = 0;                 // lattice nodes of the whole domain
  std::vector<double> exchange;     // kernel's per-body sums, kPenaltyTerms per entry
  bool measure = false;
  MeanFlow mean;
  PorousField<T> porous_field;
};

template <class T>
FluidSolver<T>::FluidSolver(const FluidParams& params, MPI_Comm comm, std::array<int, 3> dims,
                            const std::array<std::vector<double>, 3>& weights)
    : impl_(std::make_unique<FluidSolverImpl<T>>(params, comm, dims, weights)) {}

template <class T>
FluidSolver<T>::~FluidSolver() = default;

template <class T>
void FluidSolver<T>::step() {
  impl_->step();
}

template <class T>
std::int64_t FluidSolver<T>::steps() const {
  return impl_->steps;
}

template <class T>
const LocalBox& FluidSolver<T>::box() const {
  return impl_->box;
}

template <class T>
const HaloTraffic& FluidSolver<T>::halo_traffic() const {
  return impl_->halo.traffic();
}

template <class T>
const Decomposition& FluidSolver<T>::decomposition() const {
  return impl_->dec;
}

template <class T>
MPI_Comm FluidSolver<T>::comm() const {
  return impl_->dec.comm();
}

template <class T>
T FluidSolver<T>::population(int i, CellIndex cell) const {
  return impl_->population(i, cell);
}

template <class T>
T FluidSolver<T>::density(CellIndex cell) const {
  T rho = 0;
  for (int i = 0; i < d3q19::Q; ++i) rho += impl_->population(i, cell);
  return rho;
}

template <class T>
std::array<T, 3> FluidSolver<T>::velocity(CellIndex cell) const {
  using namespace d3q19;
  const auto& m = *impl_;
  T rho = 0, j[3] = {0, 0, 0};
  for (int i = 0; i < Q; ++i) {
    const T v = m.population(i, cell);
    rho += v;
    for (int k = 0; k < 3; ++k) j[k] += T(c[i][k]) * v;
  }
  std::array<T, 3> u{};
  for (int k = 0; k < 3; ++k) u[k] = j[k] / rho + T(0.5 * m.force[k]) / rho;
  const auto& pf = m.porous_field;
  if (pf.active && pf.d[cell] < 1.0f) {
    const PorousBody<T> b = pf.body[cell] >= 0 ? pf.bodies[pf.body[cell]] : PorousBody<T>{};
    const auto p = m.box.coords(cell);
    std::array<T, 3> r;
    for (int k = 0; k < 3; ++k) {
      const bool per = m.dec.periodic(k);
      r[k] = T(m.box.offset[k] + p[k] - 1) + T(0.5) - b.centre[k];
      if (per) {  // minimum image exactly as the kernel takes it
        const T len = T(m.box.global[k]);
        r[k] -= r[k] > T(0.5) * len ? len : T(0);
        r[k] += r[k] < T(-0.5) * len ? len : T(0);
      }
    }
    const std::array<T, 3> up = solid_velocity(b, r);
    const T pen = T(1) - T(pf.d[cell]);
    for (int k = 0; k < 3; ++k) u[k] += T(0.5) * pen * (up[k] - j[k] / rho);
  }
  return u;
}

template <class T>
void FluidSolver<T>::macroscopic(std::vector<T>& rho, std::vector<T>& u) const {
  const LocalBox& b = impl_->box;
  rho.resize(std::size_t(b.interior_cells()));
  u.resize(3 * rho.size());
  std::size_t k = 0;
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x, ++k) {
        const CellIndex c = b.index(x, y, z);
        rho[k] = density(c);
        const auto v = velocity(c);
        for (int a = 0; a < 3; ++a) u[3 * k + a] = v[a];
      }
}

template <class T>
void FluidSolver<T>::set_equilibrium(CellIndex cell, T rho, std::array<T, 3> u) {
  for (int i = 0; i < d3q19::Q; ++i)
    impl_->population_ref(i, cell) = d3q19::equilibrium<T>(i, rho, u[0], u[1], u[2]);
}

template <class T>
void FluidSolver<T>::set_uniform_force(std::array<double, 3> force) {
  impl_->force = force;
}

template <class T>
std::array<double, 3> FluidSolver<T>::uniform_force() const {
  return impl_->force;
}

template <class T>
std::array<double, 3> FluidSolver<T>::applied_impulse() const {
  return impl_->impulse;
}

template <class T>
std::array<double, 3> FluidSolver<T>::momentum() const {
  using namespace d3q19;
  const LocalBox& b = impl_->box;
  std::array<double, 3> local{};
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const CellIndex cell = b.index(x, y, z);
        for (int i = 1; i < Q; ++i) {
          const double v = double(impl_->population(i, cell));
          for (int k = 0; k < 3; ++k) local[k] += c[i][k] * v;
        }
      }
  std::array<double, 3> global{};
  MPI_Allreduce(local.data(), global.data(), 3, MPI_DOUBLE, MPI_SUM, impl_->dec.comm());
  return global;
}

template <class T>
void FluidSolver<T>::interior_populations(std::vector<T>& out) const {
  const LocalBox& b = impl_->box;
  out.resize(std::size_t(d3q19::Q) * std::size_t(b.interior_cells()));
  std::size_t k = 0;
  for (int i = 0; i < d3q19::Q; ++i)
    for (int z = 1; z <= b.n[2]; ++z)
      for (int y = 1; y <= b.n[1]; ++y)
        for (int x = 1; x <= b.n[0]; ++x) out[k++] = impl_->population(i, b.index(x, y, z));
}

template <class T>
void FluidSolver<T>::set_interior_populations(const std::vector<T>& in) {
  const LocalBox& b = impl_->box;
  if (in.size() != std::size_t(d3q19::Q) * std::size_t(b.interior_cells()))
    throw std::invalid_argument("set_interior_populations: wrong number of values");
  // The next step reads, for each interior cell, exactly its 19 post-stream populations
  // (in the cell itself after an even count of steps, at its neighbours' slots after an odd
  // one: population_ref hides which), so writing these restores everything it reads.
  std::size_t k = 0;
  for (int i = 0; i < d3q19::Q; ++i)
    for (int z = 1; z <= b.n[2]; ++z)
      for (int y = 1; y <= b.n[1]; ++y)
        for (int x = 1; x <= b.n[0]; ++x) impl_->population_ref(i, b.index(x, y, z)) = in[k++];
}

template <class T>
SolverMemory FluidSolver<T>::memory() const {
  return {impl_->steps, impl_->force, impl_->impulse, impl_->mean};
}

template <class T>
void FluidSolver<T>::restore(const SolverMemory& m) {
  impl_->steps = m.steps;
  impl_->force = m.force;
  impl_->impulse = m.impulse;
  impl_->mean = m.mean;
}

template <class T>
MeanFlow FluidSolver<T>::mean_flow() const {
  return impl_->mean;
}

template <class T>
void FluidSolver<T>::measure_mean_flow(bool on) {
  impl_->measure = on;
}

template <class T>
PorousField<T>& FluidSolver<T>::porous() {
  return impl_->porous();
}

template <class T>
const PorousField<T>& FluidSolver<T>::porous() const {
  return impl_->porous_field;
}

template <class T>
double FluidSolver<T>::porous_row_cells() const {
  return impl_->porous_row_cells();
}

template class FluidSolver<double>;
template class FluidSolver<float>;

}  // namespace lbdem
