#pragma once
// One output time of the fluid fields in one HDF5 file, written collectively by all fluid
// ranks (MPI-IO, each rank its hyperslab). Layout, in SI units:
//   /<view>/velocity  [nz][ny][nx][3]  m/s
//   /<view>/density   [nz][ny][nx]     kg/m^3
//   /<view>/pressure  [nz][ny][nx]     Pa, p - p_0 = c_s^2 (rho - rho_0) (lattice EOS)
// with attributes time (s), step and dx (m) on the root group, and origin/spacing (m, x y z)
// on each view group. z is the slowest index, as XDMF's 3DCoRectMesh expects.
#include <mpi.h>

#include <array>
#include <string>
#include <vector>

#include "coupler_lib/output/hdf5_handle.hpp"
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

// The volume (stride 1) of one output time, written slab by slab as each rank assembles its
// state, so that no rank holds its whole block at once (the stability watch's last good state,
// docs/performance.md "Memory per cell"). The same layout as write_field_file's volume view.
// The constructor and close() are collective over `comm`; write() is not: each rank writes
// its own slabs (independent MPI-IO transfers), as many as it has, in any order.
class FieldFileWriter {
 public:
  FieldFileWriter(const std::string& path, MPI_Comm comm, const std::array<int, 3>& global,
                  const FieldQuantities& what, const UnitConverter& units, long step, double time);
  // Writes the nodes of `slab` (a part of this rank's block, in the global lattice).
  void write(const MacroFields& slab);
  // Collective: closes the file (also done by the destructor).
  void close();

 private:
  FieldView view_;
  FieldQuantities what_;
  UnitConverter units_;
  H5Handle file_, group_, dxpl_;
  std::vector<H5Handle> datasets_;
};

}  // namespace lbdem
