// Reads a one-shape catalogue from YAML and builds the shape: exercises the installed
// headers, the scene and geometry libraries and their yaml-cpp and Eigen dependencies.
#include <cstdio>
#include <exception>

#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/scene/shapes_section.hpp"

int main() {
  try {
    lbdem::Section root = lbdem::Section::load_string(
        "shapes:\n  - {name: box, kind: cube, edge: 1.0}\n", "consumer.yaml");
    const auto params = lbdem::parse_shapes(root);
    root.finish();
    const lbdem::Shape shape = lbdem::build_shape(params.at(0), 1.0 / 20);
    std::printf("cube volume %.6f\n", shape.mass.volume);
  } catch (const std::exception& e) {
    std::printf("error: %s\n", e.what());
    return 1;
  }
  return 0;
}
