#include "coupler_lib/scene/shapes_section.hpp"

namespace lbdem {

std::vector<ShapeParams> parse_shapes(Section& root) {
  std::vector<ShapeParams> out;
  for (auto& s : root.list("shapes", "catalogue of body shapes")) {
    ShapeParams sh;
    sh.name = s.require<std::string>("name", "shape name used by bodies");
    sh.kind = s.require_choice("kind", {"sphere", "cube"}, "shape kind");
    sh.size =
        s.require<double>("size", "diameter (sphere) or edge (cube) in m", Bounds::positive());
    s.finish();
    out.push_back(sh);
  }
  return out;
}

}  // namespace lbdem
