#pragma once
// The DEM's view of the scene's shape catalogue: clump, mass properties, bounding radius.
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

std::vector<Shape> build_scene_shapes(const Scene& scene);

}  // namespace lbdem
