#include "coupler_lib/scene/coupling_section.hpp"

namespace lbdem {

CouplingParams parse_coupling(Section& s) {
  CouplingParams p;
  p.record = s.get<std::string>("record", "", "HDF5 file that records every packet");
  p.margin = s.get<double>("margin", 2.0, "stencil margin in fluid cells", Bounds::non_negative());
  s.finish();
  return p;
}

}  // namespace lbdem
