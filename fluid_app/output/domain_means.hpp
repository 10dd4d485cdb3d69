#pragma once
// Domain-wide summaries of the fluid state for the time series and the stability watch,
// reduced over all fluid ranks. Means are over all lattice nodes (inside bodies the HLBM
// velocity is the body's, which is the homogenized fluid velocity there).
#include <mpi.h>

#include <array>
#include <cmath>

#include "coupler_lib/scene/units.hpp"
#include "fluid_app/output/macro_fields.hpp"

namespace lbdem {

struct DomainMeans {
  std::array<double, 3> mean_velocity{};  // m/s
  double kinetic_energy = 0;              // J, sum of rho |u|^2 / 2 dx^3 over the domain
  double mean_density = 0;                // kg/m^3
  double max_mach = 0;                    // max |u| / c_s, lattice units
};

// Collective over `comm`.
DomainMeans domain_means(const MacroFields& f, const UnitConverter& units, MPI_Comm comm);

// |u| / c_s of a lattice velocity (c_s^2 = 1/3).
inline double lattice_mach(double ux, double uy, double uz) {
  return std::sqrt(3.0 * (ux * ux + uy * uy + uz * uz));
}

}  // namespace lbdem
