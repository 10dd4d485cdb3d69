#pragma once
// The scene's shape catalogue as both programs need it: every shape of `shapes:` voxelized at
// the same spacing, with its clump, mass properties and bounding radius. The one place that
// builds it, so that the fluid and the DEM side get identical numbers.
#include <optional>
#include <vector>

#include "coupler_lib/geometry/shape.hpp"
#include "coupler_lib/geometry/shape_params.hpp"
#include "coupler_lib/scene/fluid_section.hpp"
#include "coupler_lib/scene/scene.hpp"

namespace lbdem {

// Voxel spacing for a shape: its `voxel_size` if given, else half the fluid spacing when
// there is a fluid, else size / 40 (DEM-only scenes need no fluid lattice).
double shape_voxel_spacing(const ShapeParams& params, const std::optional<FluidParams>& fluid);

// One Shape per entry of scene.shapes, in order. With fluid.hydrodynamic_radius: calibrated,
// the fluid's voxels are those of the surface moved inward by the band's radius excess
// (band_calibration.hpp); mass, inertia and clump stay the true shape's. Throws SceneError
// (the message names the scene file and the shape) for unreadable or invalid shape input.
std::vector<Shape> build_scene_shapes(const Scene& scene);

}  // namespace lbdem
