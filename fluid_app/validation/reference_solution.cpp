#include "fluid_app/validation/reference_solution.hpp"

#include <cmath>
#include <sstream>

#include "fluid_app/analytic/channel_flow.hpp"
#include "fluid_app/analytic/taylor_green.hpp"

namespace lbdem {

namespace {

constexpr const char* kAxis[3] = {"x", "y", "z"};

[[noreturn]] void refuse(const std::string& file, const ValidationParams& v,
                         const std::string& what) {
  throw SceneError(file + ": fluid.validation.case: " + v.name + " " + what);
}

bool is_wall(FaceType t) {
  return t == FaceType::wall || t == FaceType::moving_wall;
}

// The one axis with walls on both faces; every other axis must be periodic.
int channel_axis(const FluidParams& f, const ValidationParams& v, const std::string& file) {
  int axis = -1;
  for (int d = 0; d < 3; ++d) {
    const FaceType lo = f.faces[2 * d].type, hi = f.faces[2 * d + 1].type;
    if (lo == FaceType::periodic && hi == FaceType::periodic) continue;
    if (!is_wall(lo) || !is_wall(hi) || axis >= 0)
      refuse(file, v,
             "needs walls (fluid.boundaries: wall or moving_wall) on both faces of exactly one "
             "axis and periodic faces on the other two");
    axis = d;
  }
  if (axis < 0)
    refuse(file, v, "needs walls on both faces of one axis; the box is triply periodic");
  return axis;
}

}  // namespace

ReferenceSolution make_reference(const FluidParams& f, const ValidationParams& v,
                                 const std::string& file) {
  ReferenceSolution ref;
  std::ostringstream d;
  d.precision(6);
  const double nu = f.viscosity;
  if (f.control.enabled)
    refuse(file, v, "cannot be checked with fluid.mean_velocity_control on: switch it off");

  if (v.kind == ValidationCase::taylor_green) {
    for (int a = 0; a < 3; ++a)
      if (!f.periodic(a)) refuse(file, v, "needs a triply periodic box (fluid.boundaries)");
    if (f.body_force != std::array<double, 3>{})
      refuse(file, v, "needs fluid.body_force: [0, 0, 0]");
    TaylorGreen tg;
    tg.amplitude = v.amplitude;
    tg.plane = v.plane;
    tg.period = f.domain[v.plane[0]];
    tg.nu = nu;
    tg.rho = f.density;
    if (std::abs(f.domain[v.plane[1]] - tg.period) > 1e-9 * tg.period)
      refuse(file, v,
             std::string("needs a square vortex plane: fluid.domain along ") + kAxis[v.plane[0]] +
                 " and " + kAxis[v.plane[1]] + " must be equal");
    d << "Taylor-Green vortex in the " << kAxis[v.plane[0]] << kAxis[v.plane[1]]
      << " plane, L = " << tg.period << " m, U = " << tg.amplitude
      << " m/s, Re = U L / nu = " << tg.amplitude * tg.period / nu
      << ", decay time 1/(2 nu k^2) = " << 1.0 / (2.0 * nu * std::pow(tg.wavenumber(), 2)) << " s";
    ref.velocity = [tg](const std::array<double, 3>& x, double t) { return tg.velocity(x, t); };
    ref.initial_pressure = [tg](const std::array<double, 3>& x, double t) {
      return tg.pressure(x, t);
    };
    ref.description = d.str();
    return ref;
  }

  const int axis = channel_axis(f, v, file);
  const double height = f.domain[axis];
  const FaceBoundary lo = f.faces[2 * axis], hi = f.faces[2 * axis + 1];
  if (std::abs(lo.velocity[axis]) + std::abs(hi.velocity[axis]) > 0)
    refuse(file, v, "needs wall velocities parallel to the walls");

  if (v.kind == ValidationCase::poiseuille) {
    if (lo.type != FaceType::wall || hi.type != FaceType::wall)
      refuse(file, v, "needs both channel walls at rest (type: wall)");
    const std::array<double, 3> g = f.body_force;
    if (g[axis] != 0) refuse(file, v, "needs fluid.body_force parallel to the walls");
    if (g == std::array<double, 3>{}) refuse(file, v, "needs a non-zero fluid.body_force");
    d << "Poiseuille channel, walls normal to " << kAxis[axis] << ", H = " << height << " m, g = ["
      << g[0] << ", " << g[1] << ", " << g[2] << "] m/s^2, u_max = "
      << std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) * height * height / (8.0 * nu)
      << " m/s, diffusion time H^2/nu = " << height * height / nu << " s";
    ref.velocity = [axis, height, g, nu](const std::array<double, 3>& x, double t) {
      std::array<double, 3> u{};
      for (int c = 0; c < 3; ++c)
        if (g[c] != 0) u[c] = poiseuille_velocity(x[axis], height, g[c], nu, t);
      return u;
    };
  } else {
    if (lo.type != FaceType::moving_wall && hi.type != FaceType::moving_wall)
      refuse(file, v, "needs at least one channel wall of type moving_wall");
    if (f.body_force != std::array<double, 3>{})
      refuse(file, v, "needs fluid.body_force: [0, 0, 0]");
    const std::array<double, 3> u0 = lo.velocity, u1 = hi.velocity;
    d << "Couette channel, walls normal to " << kAxis[axis] << ", H = " << height
      << " m, wall velocities [" << u0[0] << ", " << u0[1] << ", " << u0[2] << "] and [" << u1[0]
      << ", " << u1[1] << ", " << u1[2] << "] m/s, diffusion time H^2/nu = " << height * height / nu
      << " s";
    ref.velocity = [axis, height, u0, u1, nu](const std::array<double, 3>& x, double t) {
      std::array<double, 3> u{};
      for (int c = 0; c < 3; ++c)
        if (c != axis && (u0[c] != 0 || u1[c] != 0))
          u[c] = couette_velocity(x[axis], height, u0[c], u1[c], nu, t);
      return u;
    };
  }
  ref.description = d.str();
  return ref;
}

}  // namespace lbdem
