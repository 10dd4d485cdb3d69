#include "fluid_app/coupling/momentum_audit.hpp"

#include <cmath>
#include <iomanip>
#include <stdexcept>

#include "coupler_lib/geometry/periodic.hpp"
#include "coupler_lib/output/series_resume.hpp"
#include "fluid_app/lattice/d3q19.hpp"

namespace lbdem {

MomentumAudit::MomentumAudit(const std::string& path, const Scene& scene,
                             const std::vector<Shape>& shapes, std::array<double, 3> net_weight,
                             MPI_Comm comm, long long resume_bytes)
    : path_(path), scene_(scene), weight_(net_weight), comm_(comm) {
  for (const Shape& s : shapes) {
    volume_.push_back(s.mass.volume);
    inertia_.push_back(s.mass.inertia);
  }
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
          "applied_py,applied_pz,fluid_lx,fluid_ly,fluid_lz,bodies_lx,bodies_ly,bodies_lz\n"
       << std::setprecision(17);
}

long long MomentumAudit::bytes() {
  if (rank_ != 0) return 0;
  out_.flush();
  return static_cast<long long>(out_.tellp());
}

namespace {

// Minimum image of a lattice offset along axis a (docs/method-loads.md: the lever arms).
double min_image(const FluidParams& f, const LocalBox& box, int a, double r) {
  if (!f.periodic(a)) return r;
  return lbdem::min_image(r, double(box.global[a]));
}

// Angular momentum about `centre` (lattice units) of this rank's interior populations.
template <class T>
Eigen::Vector3d lattice_angular_momentum(const FluidSolver<T>& solver, const FluidParams& f,
                                         const Eigen::Vector3d& centre) {
  const LocalBox& b = solver.box();
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  for (int z = 1; z <= b.n[2]; ++z)
    for (int y = 1; y <= b.n[1]; ++y)
      for (int x = 1; x <= b.n[0]; ++x) {
        const CellIndex cell = b.index(x, y, z);
        Eigen::Vector3d j = Eigen::Vector3d::Zero();
        for (int i = 1; i < d3q19::Q; ++i) {
          const double v = double(solver.population(i, cell));
          for (int a = 0; a < 3; ++a) j[a] += d3q19::c[i][a] * v;
        }
        // Global node g sits at g + 1/2 (fluid_app/porous_field.hpp).
        const int local[3] = {x, y, z};
        Eigen::Vector3d r;
        for (int a = 0; a < 3; ++a)
          r[a] = min_image(f, b, a, b.offset[a] + (local[a] - 1) + 0.5 - centre[a]);
        l += r.cross(j);
      }
  return l;
}

}  // namespace

template <class T>
void MomentumAudit::write(std::int64_t step, double time, const FluidSolver<T>& solver,
                          std::span<const BodyState> states) {
  const FluidParams& f = *scene_.fluid;
  const double momentum_unit = f.units.force() * f.units.dt;  // lattice momentum -> N s
  const LocalBox& box = solver.box();
  const Eigen::Vector3d centre(box.global[0] / 2.0, box.global[1] / 2.0, box.global[2] / 2.0);
  // Local parts: covered fluid Q (lattice units) and body momentum (SI); then the fluid's
  // angular momentum (lattice units) and the bodies' (SI).
  std::array<double, 12> local{};
  const auto& field = solver.porous();
  if (field.active)
    for (std::size_t k = 0; k < field.exchange.size(); ++k) {
      const PenaltyExchange& e = field.exchange[k];
      // The covered moment L_k is about the centre the step used; about c it gains
      // (x_k - c) x Q_k.
      Eigen::Vector3d arm, q;
      for (int a = 0; a < 3; ++a) {
        arm[a] = min_image(f, box, a, double(field.bodies[k].centre[a]) - centre[a]);
        q[a] = e.covered[a];
        local[a] += e.covered[a];
      }
      const Eigen::Vector3d moment = arm.cross(q);
      for (int a = 0; a < 3; ++a) local[6 + a] += e.covered_moment[a] + moment[a];
    }
  for (const BodyState& s : states) {
    bool mine = true;
    for (int a = 0; a < 3; ++a) {
      double x = s.x[a] / f.dx;
      if (f.periodic(a)) x = wrap_periodic(x, double(box.global[a]));
      mine = mine && x >= box.offset[a] && x < box.offset[a] + box.n[a];
    }
    if (!mine) continue;
    const auto id = static_cast<std::size_t>(s.id);
    const auto shape = static_cast<std::size_t>(s.shape);
    const double density = scene_.bodies.at(id).density;
    const double m = density * volume_.at(shape);
    for (int a = 0; a < 3; ++a) local[3 + a] += m * s.v[a];
    // I_k = rho_k R I_shape R^T, as dem_app gives the rigid body (dem_app/lammps_input.cpp).
    const Eigen::Matrix3d rot =
        Eigen::Quaterniond(s.q[0], s.q[1], s.q[2], s.q[3]).normalized().toRotationMatrix();
    Eigen::Vector3d arm, v, w;
    for (int a = 0; a < 3; ++a) {
      arm[a] = min_image(f, box, a, s.x[a] / f.dx - centre[a]) * f.dx;
      v[a] = s.v[a];
      w[a] = s.w[a];
    }
    const Eigen::Vector3d l =
        density * rot * inertia_.at(shape) * rot.transpose() * w + arm.cross(m * v);
    for (int a = 0; a < 3; ++a) local[9 + a] += l[a];
  }
  const Eigen::Vector3d lattice_l = lattice_angular_momentum(solver, f, centre);
  for (int a = 0; a < 3; ++a) local[6 + a] = lattice_l[a] - local[6 + a];
  std::array<double, 12> global{};
  MPI_Reduce(local.data(), global.data(), 12, MPI_DOUBLE, MPI_SUM, 0, comm_);
  const std::array<double, 3> j = solver.momentum();
  const std::array<double, 3> impulse = solver.applied_impulse();
  if (rank_ != 0) return;
  out_ << step << ',' << time;
  for (int a = 0; a < 3; ++a) out_ << ',' << (j[a] - global[a]) * momentum_unit;
  for (int a = 0; a < 3; ++a) out_ << ',' << global[3 + a];
  for (int a = 0; a < 3; ++a)
    out_ << ',' << impulse[a] * momentum_unit + double(step) * f.units.dt * weight_[a];
  for (int a = 0; a < 3; ++a) out_ << ',' << global[6 + a] * momentum_unit * f.dx;
  for (int a = 0; a < 3; ++a) out_ << ',' << global[9 + a];
  out_ << '\n';
  out_.flush();
}

template void MomentumAudit::write(std::int64_t, double, const FluidSolver<double>&,
                                   std::span<const BodyState>);
template void MomentumAudit::write(std::int64_t, double, const FluidSolver<float>&,
                                   std::span<const BodyState>);

}  // namespace lbdem
