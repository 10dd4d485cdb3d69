#include "fluid_app/coupling/momentum_audit.hpp"

#include <cmath>
#include <iomanip>
#include <stdexcept>

#include "coupler_lib/output/series_resume.hpp"

namespace lbdem {

MomentumAudit::MomentumAudit(const std::string& path, const Scene& scene,
                             const std::vector<Shape>& shapes, std::array<double, 3> net_weight,
                             MPI_Comm comm, long long resume_bytes)
    : path_(path), scene_(scene), weight_(net_weight), comm_(comm) {
  for (const Shape& s : shapes) volume_.push_back(s.mass.volume);
  MPI_Comm_rank(comm, &rank_);
  if (rank_ != 0) return;
  if (resume_bytes >= 0) {
    cut_series_to(path, resume_bytes);
    out_.open(path, std::ios::app);
    if (!out_) throw std::runtime_error("cannot append to the momentum audit file " + path);
    out_ << std::setprecision(17);
    return;
  }
  out_.open(path, std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot create the momentum audit file " + path);
  out_ << "step,time_s,fluid_px,fluid_py,fluid_pz,bodies_px,bodies_py,bodies_pz,applied_px,"
          "applied_py,applied_pz\n"
       << std::setprecision(17);
}

long long MomentumAudit::bytes() {
  if (rank_ != 0) return 0;
  out_.flush();
  return static_cast<long long>(out_.tellp());
}

template <class T>
void MomentumAudit::write(std::int64_t step, double time, const FluidSolver<T>& solver,
                          std::span<const BodyState> states) {
  const FluidParams& f = *scene_.fluid;
  const double momentum_unit = f.units.force() * f.units.dt;  // lattice momentum -> N s
  const LocalBox& box = solver.box();
  // Local parts: covered fluid Q (lattice units) and body momentum (SI).
  std::array<double, 6> local{};
  const auto& field = solver.porous();
  if (field.active)
    for (const PenaltyExchange& e : field.exchange)
      for (int a = 0; a < 3; ++a) local[a] += e.covered[a];
  for (const BodyState& s : states) {
    bool mine = true;
    for (int a = 0; a < 3; ++a) {
      double x = s.x[a] / f.dx;
      const double len = box.global[a];
      if (f.periodic(a)) x -= len * std::floor(x / len);
      mine = mine && x >= box.offset[a] && x < box.offset[a] + box.n[a];
    }
    if (!mine) continue;
    const auto id = static_cast<std::size_t>(s.id);
    const double m = scene_.bodies.at(id).density * volume_.at(static_cast<std::size_t>(s.shape));
    for (int a = 0; a < 3; ++a) local[3 + a] += m * s.v[a];
  }
  std::array<double, 6> global{};
  MPI_Reduce(local.data(), global.data(), 6, MPI_DOUBLE, MPI_SUM, 0, comm_);
  const std::array<double, 3> j = solver.momentum();
  const std::array<double, 3> impulse = solver.applied_impulse();
  if (rank_ != 0) return;
  out_ << step << ',' << time;
  for (int a = 0; a < 3; ++a) out_ << ',' << (j[a] - global[a]) * momentum_unit;
  for (int a = 0; a < 3; ++a) out_ << ',' << global[3 + a];
  for (int a = 0; a < 3; ++a)
    out_ << ',' << impulse[a] * momentum_unit + double(step) * f.units.dt * weight_[a];
  out_ << '\n';
  out_.flush();
}

template void MomentumAudit::write(std::int64_t, double, const FluidSolver<double>&,
                                   std::span<const BodyState>);
template void MomentumAudit::write(std::int64_t, double, const FluidSolver<float>&,
                                   std::span<const BodyState>);

}  // namespace lbdem
