#include "coupler_lib/scene/bodies_section.hpp"

namespace lbdem {

std::vector<BodyParams> parse_bodies(Section& root, const std::vector<ShapeParams>& shapes) {
  std::vector<BodyParams> out;
  for (auto& s : root.list("bodies", "list of bodies")) {
    BodyParams b;
    const auto name = s.require<std::string>("shape", "name of a shape in the catalogue");
    b.shape = -1;
    for (size_t i = 0; i < shapes.size(); ++i)
      if (shapes[i].name == name) b.shape = static_cast<int>(i);
    if (b.shape < 0) s.fail("shape", "no shape named '" + name + "' in the shapes catalogue");
    b.position = s.require_vec3("position", "centre of mass in m");
    b.velocity = s.vec3("velocity", {0, 0, 0}, "initial velocity in m/s");
    b.angular_velocity = s.vec3("angular_velocity", {0, 0, 0}, "initial angular velocity in rad/s");
    b.density = s.require<double>("density", "body density in kg/m^3", Bounds::positive());
    s.finish();
    out.push_back(b);
  }
  return out;
}

}  // namespace lbdem
