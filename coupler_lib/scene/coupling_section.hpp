#pragma once
// The `coupling:` section: what both sides agree on for exchanging packets.
#include <string>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct CouplingParams {
  std::string record;   // HDF5 file recording every packet; empty = no recording
  double margin = 2.0;  // stencil margin in fluid cells added to a body's bounding sphere
};

CouplingParams parse_coupling(Section& s);

}  // namespace lbdem
