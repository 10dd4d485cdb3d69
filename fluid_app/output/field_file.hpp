#pragma once
// One output time of the fluid fields in one HDF5 file, written collectively by all fluid
// ranks (MPI-IO, each rank its hyperslab). Layout, in SI units:
//   /<view>/velocity  [nz][ny][nx][3]  m/s
//   /<view>/density   [nz][ny][nx]     kg/m^3
//   /<view>/pressure  [nz][ny][nx]     Pa, p - p_0 = c_s^2 (rho - rho_0) (lattice EOS)
// with attributes time (s), step and dx (m) on the root group, and origin/spacing (m, x y z)
// on each view group. z is the slowest index, as XDMF's 3DCoRectMesh expects.
#include <mpi.h>

#include <string>
#include <vector>

#include "coupler_lib/scene/units.hpp"
#include "fluid_app/output/field_view.hpp"
#include "fluid_app/output/macro_fields.hpp"

namespace lbdem {

struct FieldQuantities {
  bool velocity = true;
  bool density = false;
  bool pressure = false;
  bool double_precision = false;
};

// SI values of the lattice state, as written to files (lattice EOS p = c_s^2 rho).
double si_velocity(double u_lattice, const UnitConverter& units);
double si_density(double rho_lattice, const UnitConverter& units);
double si_pressure(double rho_lattice, const UnitConverter& units);

// Collective over `comm`: every rank calls it with its own block.
void write_field_file(const std::string& path, MPI_Comm comm, const std::vector<FieldView>& views,
                      const FieldQuantities& what, const MacroFields& fields,
                      const UnitConverter& units, long step, double time);

}  // namespace lbdem
