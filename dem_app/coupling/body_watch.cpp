#include "dem_app/coupling/body_watch.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <sstream>

#include "coupler_lib/output/gather.hpp"
#include "coupler_lib/scene/body_placement.hpp"

namespace lbdem {

namespace {

bool finite(const BodyState& s) {
  for (double v : s.x)
    if (!std::isfinite(v)) return false;
  for (double v : s.q)
    if (!std::isfinite(v)) return false;
  for (double v : s.v)
    if (!std::isfinite(v)) return false;
  for (double v : s.w)
    if (!std::isfinite(v)) return false;
  return true;
}

Eigen::Vector3d vec(const double* v) {
  return {v[0], v[1], v[2]};
}

std::string when_text(std::int64_t step, double time) {
  std::ostringstream t;
  t.precision(6);
  t << " at step " << step << " (t = " << time << " s)";
  return t.str();
}

std::string non_finite(const std::vector<BodyState>& states, const std::string& when) {
  for (const BodyState& s : states)
    if (!finite(s)) {
      std::ostringstream m;
      m << "the bodies are unstable: body " << s.id << " has a non-finite state" << when
        << "; likely cause: the DEM integration diverged (a contact stiffer than dem.dt "
           "resolves, or a non-finite load from the fluid); what to change: lower dem.dt or "
           "dem.dt_fraction, or soften dem.material.young_modulus";
      return m.str();
    }
  return {};
}

std::string too_fast(const std::vector<BodyState>& states, const std::string& when,
                     const DemSetup& setup, const BodyWatchLimits& limits) {
  if (limits.max_speed <= 0) return {};
  for (const BodyState& s : states) {
    const double r = setup.shapes[static_cast<size_t>(s.shape)].bounding_radius;
    const double speed = vec(s.v).norm() + vec(s.w).norm() * r;
    if (speed > limits.max_speed) {
      std::ostringstream m;
      m.precision(4);
      m << "the bodies are unstable: body " << s.id << " at (" << s.x[0] << ", " << s.x[1] << ", "
        << s.x[2] << ") m moves at " << speed << " m/s (|v| + |omega| r)" << when
        << ", above the fluid's limit " << limits.max_speed
        << " m/s (fluid.stability.max_mach times the lattice sound speed); likely "
           "cause: a load or contact impulse the coupling cannot resolve (body much lighter "
           "than the fluid, too stiff a contact, or a too fast start); what to change: refine "
           "fluid.dx or raise fluid.tau (a faster lattice), lower the bodies' initial "
           "velocities, or raise their density";
      return m.str();
    }
  }
  return {};
}

std::string overlapping(const std::vector<BodyState>& all, const std::string& when,
                        const DemSetup& setup, const BodyWatchLimits& limits) {
  std::vector<BodyPose> poses;
  for (const BodyState& s : all)
    poses.push_back(
        {s.shape, vec(s.x),
         Eigen::Quaterniond(s.q[0], s.q[1], s.q[2], s.q[3]).normalized().toRotationMatrix()});
  const auto o =
      deepest_clump_overlap(setup.shapes, poses, setup.box_lo, setup.box_hi, setup.params.periodic);
  if (!o || o->fraction <= limits.max_overlap) return {};
  std::ostringstream m;
  m.precision(4);
  m << "the bodies are unstable: bodies " << all[o->a].id << " and " << all[o->b].id
    << " overlap by " << o->depth << " m, " << o->fraction
    << " of the smaller clump-sphere radius, at (" << o->at[0] << ", " << o->at[1] << ", "
    << o->at[2] << ") m" << when << " (limit dem.max_overlap = " << limits.max_overlap
    << "); likely cause: a contact too soft for the approach speed, or a DEM step too "
       "coarse for its stiffness; what to change: raise dem.material.young_modulus, lower "
       "dem.dt or dem.dt_fraction, or lower the approach speed";
  return m.str();
}

// The message of the lowest rank that has one, on every rank (empty when none has): the
// finding a gather in rank order would have reported first, for O(1) bytes per rank.
std::string first_in_rank_order(const std::string& mine, MPI_Comm side) {
  int rank = 0, size = 1;
  MPI_Comm_rank(side, &rank);
  MPI_Comm_size(side, &size);
  int first = mine.empty() ? size : rank;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, side);
  if (first == size) return {};
  std::string message = mine;
  int n = static_cast<int>(message.size());
  MPI_Bcast(&n, 1, MPI_INT, first, side);
  message.resize(static_cast<size_t>(n));
  MPI_Bcast(message.data(), n, MPI_CHAR, first, side);
  return message;
}

}  // namespace

BodyWatchLimits body_watch_limits(const Scene& scene) {
  BodyWatchLimits l;
  if (scene.fluid) {
    const double c_s = scene.fluid->units.velocity() / std::sqrt(3.0);
    l.max_speed = scene.fluid->output.stability.max_mach * c_s;
  }
  if (scene.dem) l.max_overlap = scene.dem->max_overlap;
  return l;
}

std::string check_bodies(const std::vector<BodyState>& owned, std::int64_t step, double time,
                         const DemSetup& setup, const BodyWatchLimits& limits, bool overlaps,
                         MPI_Comm side) {
  // Each rank checks its own bodies; only the overlap search (at the agreed steps) needs the
  // neighbours' bodies and gathers them.
  const std::string when = when_text(step, time);
  std::string message = first_in_rank_order(non_finite(owned, when), side);
  if (message.empty()) message = first_in_rank_order(too_fast(owned, when, setup, limits), side);
  if (!message.empty() || !overlaps || limits.max_overlap <= 0) return message;
  int rank = 0;
  MPI_Comm_rank(side, &rank);
  const std::vector<BodyState> all = gather_to_root(std::span<const BodyState>(owned), side);
  return first_in_rank_order(rank == 0 ? overlapping(all, when, setup, limits) : std::string(),
                             side);
}

}  // namespace lbdem
