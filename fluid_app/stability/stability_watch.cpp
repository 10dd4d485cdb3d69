#include "fluid_app/stability/stability_watch.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <utility>

#include "fluid_app/output/field_file.hpp"
#include "fluid_app/output/xdmf_file.hpp"

namespace lbdem {

LocalScan scan_block(const MacroFields& f, double max_mach) {
  LocalScan s;
  const FieldBlock& b = f.box;
  // Global x-fastest order of the nodes, so "first" means the same on any decomposition.
  auto global_order = [&](int i, int j, int k) {
    return (static_cast<long long>(k + b.lo[2]) * b.global[1] + (j + b.lo[1])) * b.global[0] +
           (i + b.lo[0]);
  };
  long long first = std::numeric_limits<long long>::max();
  // Mach = sqrt(3 |u|^2): compare |u|^2 with max_mach^2 / 3, no root on the common path.
  const double limit_u2 = max_mach * max_mach / 3.0;
  double max_u2 = 0;
  for (int k = 0; k < b.n[2]; ++k)
    for (int j = 0; j < b.n[1]; ++j)
      for (int i = 0; i < b.n[0]; ++i) {
        const std::size_t c = b.index(i, j, k);
        const double rho = f.rho[c], ux = f.u[3 * c], uy = f.u[3 * c + 1], uz = f.u[3 * c + 2];
        const double u2 = ux * ux + uy * uy + uz * uz;
        // Written so that NaN fails every comparison and leaves the fast path.
        if (rho > 0 && rho <= std::numeric_limits<double>::max() && u2 <= limit_u2) {
          max_u2 = std::max(max_u2, u2);
          continue;
        }
        const double mach = std::sqrt(3.0 * u2);
        Instability kind = Instability::mach;
        if (!std::isfinite(rho) || !std::isfinite(mach))
          kind = Instability::not_finite;
        else if (rho <= 0)
          kind = Instability::density;
        if (std::isfinite(u2)) max_u2 = std::max(max_u2, u2);
        if (kind < s.kind) continue;
        if (kind > s.kind) {
          s.kind = kind;
          s.bad_cells = 0;
          first = std::numeric_limits<long long>::max();
          s.mach = -1;
        }
        ++s.bad_cells;
        const long long order = global_order(i, j, k);
        const bool better = kind == Instability::mach ? mach > s.mach : order < first;
        if (better) {
          first = order;
          s.cell = {i + b.lo[0], j + b.lo[1], k + b.lo[2]};
          s.rho = rho;
          s.u = {ux, uy, uz};
          s.mach = mach;
        }
      }
  s.max_mach = std::sqrt(3.0 * max_u2);
  return s;
}

void merge_scan(LocalScan& into, const LocalScan& part, const std::array<int, 3>& global) {
  const double max_mach = std::max(into.max_mach, part.max_mach);
  if (part.kind > into.kind) {
    into = part;
  } else if (part.kind == into.kind && part.kind != Instability::none) {
    auto order = [&](const std::array<int, 3>& c) {
      return (static_cast<long long>(c[2]) * global[1] + c[1]) * global[0] + c[0];
    };
    const bool better = part.kind == Instability::mach ? part.mach > into.mach
                                                       : order(part.cell) < order(into.cell);
    const long long bad = into.bad_cells + part.bad_cells;
    if (better) into = part;
    into.bad_cells = bad;
  }
  into.max_mach = max_mach;
}

StabilityWatch::StabilityWatch(const StabilityParams& params, const UnitConverter& units,
                               MPI_Comm comm, std::string last_good_file)
    : params_(params), units_(units), comm_(comm), last_good_file_(std::move(last_good_file)) {}

namespace {

// The node every rank reports: largest Mach for Mach trouble, else the first node in global
// order. Ties between ranks go to the lowest rank (MPI_MAXLOC / MPI_MINLOC).
int reporting_rank(const LocalScan& s, Instability kind, const FieldBlock& b, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  struct {
    double value;
    int rank;
  } mine{0.0, rank}, best{0.0, 0};
  if (kind == Instability::mach) {
    mine.value = s.kind == kind ? s.mach : -1.0;
    MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
  } else {
    const double order =
        (static_cast<double>(s.cell[2]) * b.global[1] + s.cell[1]) * b.global[0] + s.cell[0];
    mine.value = s.kind == kind ? order : std::numeric_limits<double>::infinity();
    MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
  }
  return best.rank;
}

}  // namespace

void StabilityWatch::remove_last_good() const {
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank != 0) return;
  std::filesystem::path h5(last_good_file_);
  std::filesystem::remove(h5);
  std::filesystem::remove(h5.replace_extension(".xdmf"));
}

std::optional<StabilityFailure> StabilityWatch::check(long step, double time,
                                                      const MacroFields& fields) {
  return check(step, time, fields.box, std::max(fields.box.n[2], 1),
               [&](int, int) -> const MacroFields& { return fields; });
}

std::optional<StabilityFailure> StabilityWatch::check(long step, double time, const FieldBlock& box,
                                                      int planes, const Slabs& slabs) {
  // The last good file's layout: what the field output writes, in float (a diagnostic
  // snapshot; the run's own precision is in its checkpoints).
  const FieldQuantities quantities{true, true, true, false};
  const std::string candidate = last_good_file_ + ".tmp";
  LocalScan s;
  {
    FieldFileWriter file(candidate, comm_, box.global, quantities, units_, step, time);
    for (int z0 = 0; z0 < box.n[2]; z0 += planes) {
      const MacroFields& slab = slabs(z0, std::min(z0 + planes, box.n[2]));
      merge_scan(s, scan_block(slab, params_.max_mach), box.global);
      file.write(slab);
    }
  }  // closed by every rank before the verdict below is reduced
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  int kind = static_cast<int>(s.kind);
  MPI_Allreduce(MPI_IN_PLACE, &kind, 1, MPI_INT, MPI_MAX, comm_);
  if (kind == static_cast<int>(Instability::none)) {
    double mach = s.max_mach;
    MPI_Allreduce(MPI_IN_PLACE, &mach, 1, MPI_DOUBLE, MPI_MAX, comm_);
    if (rank == 0) {
      // A rename over the old file: at any moment one whole last good file exists.
      const std::filesystem::path h5(last_good_file_);
      std::filesystem::rename(candidate, h5);
      std::filesystem::path xdmf = h5;
      xdmf.replace_extension(".xdmf");
      write_file_atomically(xdmf.string(), xdmf_text(volume_view(box.global, 1), quantities,
                                                     units_.dx, {{time, h5.filename().string()}}));
    }
    MPI_Barrier(comm_);  // no rank creates the next candidate before the rename
    last_good_step_ = step;
    last_good_time_ = time;
    last_good_mach_ = mach;
    return std::nullopt;
  }
  if (rank == 0) std::filesystem::remove(candidate);

  InstabilityReport r;
  r.kind = static_cast<Instability>(kind);
  const int root = reporting_rank(s, r.kind, box, comm_);
  // One node's description travels from the rank that holds it to everyone.
  std::array<double, 8> node{double(s.cell[0]),
                             double(s.cell[1]),
                             double(s.cell[2]),
                             s.rho,
                             s.u[0],
                             s.u[1],
                             s.u[2],
                             s.mach};
  MPI_Bcast(node.data(), 8, MPI_DOUBLE, root, comm_);
  long long bad = s.kind == r.kind ? s.bad_cells : 0;
  MPI_Allreduce(MPI_IN_PLACE, &bad, 1, MPI_LONG_LONG, MPI_SUM, comm_);
  r.cell = {int(node[0]), int(node[1]), int(node[2])};
  r.rho = node[3];
  r.u = {node[4], node[5], node[6]};
  r.mach = node[7];
  r.bad_cells = bad;
  r.step = step;
  r.time = time;
  r.last_good_step = last_good_step_;
  r.last_good_time = last_good_time_;
  r.last_good_mach = last_good_mach_;
  r.max_mach = params_.max_mach;

  StabilityFailure failure;
  failure.report = r;
  if (last_good_step_ >= 0) failure.last_good_file = last_good_file_;
  failure.message = describe_instability(r, units_, failure.last_good_file);
  return failure;
}

}  // namespace lbdem
