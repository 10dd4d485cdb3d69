#pragma once
// The validation measure: the L2 relative error of the velocity field against a reference,
//   e = sqrt( sum |u - u_ref|^2 / sum |u_ref|^2 )   over all lattice nodes,
// reduced over the fluid ranks.
#include <mpi.h>

#include "coupler_lib/scene/units.hpp"
#include "fluid_app/output/macro_fields.hpp"
#include "fluid_app/validation/reference_solution.hpp"

namespace lbdem {

struct VelocityError {
  double l2_relative = 0;
  double max_abs = 0;  // m/s, largest |u - u_ref| at a node
};

// Collective over `comm`; `time` in s.
VelocityError velocity_error(const MacroFields& f, const UnitConverter& units,
                             const ReferenceSolution& ref, double time, MPI_Comm comm);

}  // namespace lbdem
