#pragma once
// The `shapes:` catalogue of a scene: what each body looks like.
#include <string>
#include <vector>

#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

struct ShapeParams {
  std::string name;
  std::string kind;  // sphere | cube | ...
  double size = 0;   // m: sphere diameter, cube edge
};

std::vector<ShapeParams> parse_shapes(Section& root);

}  // namespace lbdem
