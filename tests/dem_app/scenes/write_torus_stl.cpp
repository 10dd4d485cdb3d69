// Writes the torus of tests/dem_app/scenes/torus_small.yaml to the path given: ring 5 mm, tube
// 2 mm, 24 x 12 segments, axis z, centred at the origin (coupler_lib/geometry/mesh_primitives).
#include <cstdio>

#include "coupler_lib/geometry/mesh_primitives.hpp"
#include "coupler_lib/geometry/stl_io.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_torus_stl FILE.stl\n");
    return 2;
  }
  lbdem::write_stl_ascii(argv[1], lbdem::torus_mesh(5e-3, 2e-3, 24, 12), "torus");
  return 0;
}
