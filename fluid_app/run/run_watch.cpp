#include "fluid_app/run/run_watch.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "fluid_app/validation/velocity_error.hpp"

namespace lbdem {

template <class T>
void fill_macro_fields(const FluidSolver<T>& solver, MacroFields& out) {
  const LocalBox& b = solver.box();
  out.resize(FieldBlock{b.global, b.offset, b.n});
  if constexpr (std::is_same_v<T, double>) {
    solver.macroscopic(out.rho, out.u);
  } else {
    std::vector<T> rho, u;
    solver.macroscopic(rho, u);
    out.rho.assign(rho.begin(), rho.end());
    out.u.assign(u.begin(), u.end());
  }
}

namespace {

// Starts the run from the reference solution at t = 0: equilibrium populations at the
// analytic velocity and at the density of the analytic pressure (p = c_s^2 rho).
template <class T>
void set_initial_state(FluidSolver<T>& solver, const ReferenceSolution& ref,
                       const UnitConverter& units) {
  const LocalBox& b = solver.box();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const std::array<double, 3> pos{(b.offset[0] + x - 0.5) * units.dx,
                                        (b.offset[1] + y - 0.5) * units.dx,
                                        (b.offset[2] + z - 0.5) * units.dx};
        const std::array<double, 3> u = ref.velocity(pos, 0.0);
        const double rho = 1.0 + 3.0 * ref.initial_pressure(pos, 0.0) / units.pressure();
        solver.set_equilibrium(
            b.index(x, y, z), T(rho),
            {T(u[0] / units.velocity()), T(u[1] / units.velocity()), T(u[2] / units.velocity())});
      }
}

std::string last_good_path(const FluidOutputParams& p, const std::string& scene_name) {
  if (!p.stability.last_good.empty()) return p.stability.last_good;
  return (std::filesystem::path(p.directory) / (scene_name + "_last_good.h5")).string();
}

}  // namespace

template <class T>
RunWatch<T>::RunWatch(AppContext& ctx, FluidRun<T>& run, long long series_resume_bytes)
    : ctx_(ctx), run_(run), params_(run.params().output) {
  const FluidParams& fp = run.params();
  // The side communicator, not the solver's: the same ranks in the same order (the Cartesian
  // grid keeps them), and it outlives a solver replaced by in-run rebalancing.
  const MPI_Comm comm = ctx.side_comm;
  if (params_.writes_files())
    output_ = std::make_unique<FluidOutput>(params_, fp.units, ctx.scene.name, comm, fp.cells,
                                            series_resume_bytes);
  if (params_.stability.interval > 0) {
    const std::string lg = last_good_path(params_, ctx.scene.name);
    if (lg.find('/') != std::string::npos)
      make_output_directory(std::filesystem::path(lg).parent_path().string(), comm);
    stability_ = std::make_unique<StabilityWatch>(params_.stability, fp.units, comm, lg);
  }
  if (params_.validation) {
    reference_ = make_reference(fp, *params_.validation, ctx.scene.file);
    ctx.log->info("validation {}: {}", params_.validation->name, reference_->description);
    if (reference_->initial_pressure) set_initial_state(run.solver(), *reference_, fp.units);
  }
  run.add_observer([this](const FluidSolver<T>& s, const StepInfo& i) { observe(s, i); });
  started_ = std::chrono::steady_clock::now();
}

namespace {

// Planes of the local block per slab when the stability check runs without field output:
// the state is assembled a slab at a time (32 B per node in double, and the slab's float
// samples for the last good file), never whole.
constexpr int kSlabPlanes = 2;

// Density and velocity of local planes z0 .. z1-1 (0-based) into `out`, exactly as
// fill_macro_fields writes them (the solver's density and velocity per node).
template <class T>
void fill_slab(const FluidSolver<T>& solver, int z0, int z1, MacroFields& out) {
  const LocalBox& b = solver.box();
  out.resize(FieldBlock{
      b.global, {b.offset[0], b.offset[1], b.offset[2] + z0}, {b.n[0], b.n[1], z1 - z0}});
  std::size_t k = 0;
  for (int z = z0 + 1; z <= z1; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x, ++k) {
        const CellIndex c = b.index(x, y, z);
        out.rho[k] = double(solver.density(c));
        const auto v = solver.velocity(c);
        for (int a = 0; a < 3; ++a) out.u[3 * k + a] = double(v[a]);
      }
}

}  // namespace

template <class T>
void RunWatch<T>::observe(const FluidSolver<T>& solver, const StepInfo& info) {
  if (failure_) return;
  const long step = static_cast<long>(info.step);
  const bool check = stability_ && (stability_->due(step) || (extra_ && extra_(step)));
  const bool write = output_ && output_->due(step);
  if (!check && !write) return;
  if (check && !write) {
    // One pass over the lattice: each slab is assembled, scanned and written to the last good
    // candidate (StabilityWatch::check), then dropped.
    const LocalBox& b = solver.box();
    MacroFields slab;
    failure_ = stability_->check(step, info.time, FieldBlock{b.global, b.offset, b.n}, kSlabPlanes,
                                 [&](int z0, int z1) -> const MacroFields& {
                                   fill_slab(solver, z0, z1, slab);
                                   return slab;
                                 });
    if (failure_ && ctx_.rank == 0) ctx_.log->error("{}", failure_->message);
    return;
  }
  fill_macro_fields(solver, fields_);
  if (check) {
    failure_ = stability_->check(step, info.time, fields_);
    if (failure_) {
      // Every rank holds the same diagnosis; one prints it.
      if (ctx_.rank == 0) ctx_.log->error("{}", failure_->message);
      return;
    }
  }
  output_->write(step, info.time, fields_);
}

template <class T>
int RunWatch<T>::finish() {
  if (failure_) return kExitUnstable;
  if (stability_) stability_->remove_last_good();
  if (!reference_) return 0;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const StepInfo info = run_.info();
  fill_macro_fields(run_.solver(), fields_);
  const VelocityError e =
      velocity_error(fields_, run_.params().units, *reference_, info.time, run_.solver().comm());
  const ValidationParams& v = *params_.validation;
  const auto& n = run_.params().cells;
  if (ctx_.rank == 0) {
    // One parseable line on stdout for tools/convergence_study.
    std::printf(
        "validation %s: cells %dx%dx%d, steps %lld, t = %.6g s, L2 relative velocity error "
        "%.6e, max |u - u_ref| %.3e m/s, run time %.4g s\n",
        v.name.c_str(), n[0], n[1], n[2], static_cast<long long>(info.step), info.time,
        e.l2_relative, e.max_abs, seconds);
    std::fflush(stdout);
  }
  if (v.tolerance > 0 && !(e.l2_relative <= v.tolerance)) {
    ctx_.log->error(
        "validation {}: L2 relative velocity error {:.4e} exceeds the tolerance {} "
        "(fluid.validation.tolerance)",
        v.name, e.l2_relative, v.tolerance);
    return kExitValidationFailed;
  }
  return 0;
}

template class RunWatch<double>;
template class RunWatch<float>;
template void fill_macro_fields(const FluidSolver<double>&, MacroFields&);
template void fill_macro_fields(const FluidSolver<float>&, MacroFields&);

}  // namespace lbdem
