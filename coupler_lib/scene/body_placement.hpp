#pragma once
// Where the walls and bodies of a scene start: walls in the box, bodies inside it, clear of the
// walls, not overlapping each other. Both programs run this on the whole scene at start-up
// (scene_checks.hpp), and the DEM runs it again on the box it resolved, so one implementation
// answers for both.
#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/scene/bodies_section.hpp"
#include "coupler_lib/scene/dem_section.hpp"

namespace lbdem {

// Largest distance of a clump sphere's surface from the centroid (LAMMPS's body extent).
double clump_extent(const Shape& shape);

// Throws SceneError (prefixed with `file`) for a wall of p.walls on a periodic axis or outside
// the box, and for a body that refers to a missing shape, has a
// non-positive density, reaches outside the box [box_lo, box_hi] on a non-periodic axis (its
// centre, on a periodic one), crosses one of p.walls, or overlaps another body's clump spheres
// (minimum image on the periodic axes of p).
void check_body_placement(const std::string& file, const std::vector<Shape>& shapes,
                          const std::vector<BodyParams>& bodies,
                          const std::array<double, 3>& box_lo, const std::array<double, 3>& box_hi,
                          const DemParams& p);

// A body's pose for the overlap search: shape index, centre (m), rotation shape -> space.
struct BodyPose {
  int shape = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
};

// The deepest overlap of two bodies' clump spheres (indices into `bodies`): depth in m, the
// depth as a fraction of the smaller of the two spheres' radii, and where it is.
struct ClumpOverlap {
  size_t a = 0, b = 0;
  double depth = 0;
  double fraction = 0;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
};

// Cell list on the centres, minimum image on the periodic axes; nullopt when no two bodies
// touch. Used at start-up (no overlap allowed) and by the coupled stability watch.
std::optional<ClumpOverlap> deepest_clump_overlap(const std::vector<Shape>& shapes,
                                                  const std::vector<BodyPose>& bodies,
                                                  const std::array<double, 3>& box_lo,
                                                  const std::array<double, 3>& box_hi,
                                                  const std::array<bool, 3>& periodic);

}  // namespace lbdem
