#include "fluid_app/stability/stability_diagnosis.hpp"

#include <cmath>
#include <sstream>

namespace lbdem {

namespace {

std::string quantity(const InstabilityReport& r, const UnitConverter& units) {
  std::ostringstream s;
  s.precision(4);
  switch (r.kind) {
    case Instability::mach:
      s << "Mach " << r.mach << " > " << r.max_mach
        << " (fluid.stability.max_mach): |u| = " << r.mach / std::sqrt(3.0) * units.velocity()
        << " m/s";
      break;
    case Instability::density:
      s << "density " << r.rho * units.rho << " kg/m^3 <= 0 (lattice rho " << r.rho << ")";
      break;
    case Instability::not_finite:
      s << "state is not finite (rho " << r.rho << ", u [" << r.u[0] << ", " << r.u[1] << ", "
        << r.u[2] << "] in lattice units)";
      break;
    case Instability::none:
      s << "no instability";
      break;
  }
  return s.str();
}

// Why it happened and which scene keys to change. In these units u_lattice = u dt/dx =
// u (tau - 1/2) dx / (3 nu) (units.hpp), so at fixed tau the Mach number scales with dx and at
// fixed dx with tau - 1/2.
std::string advice(const InstabilityReport& r, const UnitConverter& units) {
  std::ostringstream s;
  s.precision(4);
  const double tau = units.tau;
  if (r.kind == Instability::mach) {
    const double f = r.max_mach / r.mach;
    const double min_tau = UnitLimits{}.min_tau;
    s << "likely cause: the flow is too fast for the lattice (lattice velocity u dt/dx = "
         "u (tau - 1/2) dx / (3 nu)). Change the scene: refine fluid.dx to <= "
      << units.dx * f << " m (Mach scales with dx at fixed tau), ";
    if (0.5 + (tau - 0.5) * f >= min_tau)
      s << "or lower fluid.tau to <= " << 0.5 + (tau - 0.5) * f
        << " (Mach scales with tau - 1/2 at fixed dx; tau >= " << min_tau << "), ";
    s << "or lower the driving (body force, wall or body velocity).";
    return s.str();
  }
  s << "likely cause: ";
  if (tau < 0.55) s << "tau = " << tau << " is close to 1/2, where BGK is only marginally stable; ";
  if (r.last_good_mach > 0.5 * r.max_mach)
    s << "the velocity was already high (max Mach " << r.last_good_mach
      << " at the last good check); ";
  s << "the solution grew without bound between two checks. Change the scene: raise fluid.tau "
       "(more viscous damping per step), refine fluid.dx, or lower the driving force or "
       "velocity; a smaller fluid.stability.interval catches the growth earlier.";
  return s.str();
}

}  // namespace

std::string describe_instability(const InstabilityReport& r, const UnitConverter& units,
                                 const std::string& last_good_file) {
  std::ostringstream s;
  s.precision(6);
  s << "fluid is unstable: " << quantity(r, units) << "\n"
    << "  where: cell (" << r.cell[0] << ", " << r.cell[1] << ", " << r.cell[2] << ") at x = ("
    << (r.cell[0] + 0.5) * units.dx << ", " << (r.cell[1] + 0.5) * units.dx << ", "
    << (r.cell[2] + 0.5) * units.dx << ") m; " << r.bad_cells << " node(s) affected\n"
    << "  when: step " << r.step << ", t = " << r.time << " s\n"
    << "  " << advice(r, units) << "\n";
  if (!last_good_file.empty())
    s << "  last good state (step " << r.last_good_step << ", t = " << r.last_good_time
      << " s) written to " << last_good_file;
  else
    s << "  no check had passed before, so no last good state was written";
  return s.str();
}

}  // namespace lbdem
