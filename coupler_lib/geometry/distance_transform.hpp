#pragma once
// Exact Euclidean distance transform on a voxel lattice (separable lower-envelope-of-
// parabolas algorithm of Felzenszwalb & Huttenlocher, Theory of Computing 8, 2012).
#include <vector>

#include "coupler_lib/geometry/shape.hpp"

namespace lbdem {

// For every voxel, the distance (m) from its centre to the centre of the nearest voxel of
// the other kind (solid <-> empty). The surface lies about h/2 inside that distance.
std::vector<double> distance_to_other_kind(const Voxels& voxels);

// For every voxel, the distance (m) from its centre to the centre of the nearest solid voxel
// (0 on solid voxels; infinite everywhere when none is solid).
std::vector<double> distance_to_solid(const Voxels& voxels);

}  // namespace lbdem
