#pragma once
// The `shapes:` catalogue of a scene: what each body looks like (docs/user-guide.md, "Shapes and
// clumps").
//
//   shapes:
//     - name: cube
//       kind: cube            # sphere | cube | cuboid | ellipsoid | stl
//       edge: 0.283e-3        # sphere: diameter; cube: edge; cuboid: edges [a,b,c];
//                             # ellipsoid: semi_axes [a,b,c]; stl: file + scale
//       clump: {file: ../shapes/cube_489_surface.clump, scale: 0.283e-3}
//       voxel_size: 5e-6      # optional; default: half the fluid spacing (the fluid's
//                             # reference lattice: half of that)
#include <vector>

#include "coupler_lib/geometry/shape_params.hpp"
#include "coupler_lib/scene/yaml_reader.hpp"

namespace lbdem {

// The schema of one entry of `shapes:`.
const MappingSchema& shape_schema();
std::vector<ShapeParams> parse_shapes(Section& root);

}  // namespace lbdem
