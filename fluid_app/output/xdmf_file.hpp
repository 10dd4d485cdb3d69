#pragma once
// The XDMF description of a series of HDF5 field files, through the shared XDMF 3 writer
// (coupler_lib/output/xdmf.hpp): one lattice grid per output time, which ParaView opens
// directly. Nodes are the lattice nodes at the cell centres.
#include <string>
#include <vector>

#include "coupler_lib/output/atomic_file.hpp"
#include "fluid_app/output/field_file.hpp"
#include "fluid_app/output/field_view.hpp"

namespace lbdem {

struct XdmfStep {
  double time = 0;
  std::string h5_file;  // path relative to the XDMF file
};

// The complete XDMF text for `view` over all `steps`.
std::string xdmf_text(const FieldView& view, const FieldQuantities& what, double dx,
                      const std::vector<XdmfStep>& steps);

}  // namespace lbdem
