#include "coupler_lib/scene/shape_catalogue.hpp"

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/build_shape.hpp"

namespace lbdem {

std::vector<Shape> build_scene_shapes(const Scene& scene) {
  std::vector<Shape> out;
  for (const auto& p : scene.shapes) {
    try {
      out.push_back(build_shape(p, shape_voxel_spacing(p, scene.fluid)));
    } catch (const ShapeError& e) {
      throw SceneError(e.what());
    }
  }
  return out;
}

}  // namespace lbdem
