#include "coupler_lib/scene/shape_catalogue.hpp"

#include <string>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/build_shape.hpp"
#include "coupler_lib/scene/band_calibration.hpp"

namespace lbdem {

namespace {

// Without a fluid lattice, the voxelization only feeds mass properties: 40 voxels across
// the characteristic length keeps the inertia of curved shapes within about 1 %.
constexpr double kCellsAcrossWithoutFluid = 40;

}  // namespace

double shape_voxel_spacing(const ShapeParams& p, const std::optional<FluidParams>& fluid) {
  if (p.voxel_size > 0) return p.voxel_size;
  if (fluid) return 0.5 * fluid->dx;
  return p.size / kCellsAcrossWithoutFluid;
}

std::vector<Shape> build_scene_shapes(const Scene& scene) {
  std::vector<Shape> out;
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    ShapeParams p = scene.shapes[i];
    if (scene.fluid && scene.fluid->hydrodynamic_radius == HydrodynamicRadius::calibrated)
      p.hydrodynamic_offset =
          *band_radius_excess_cells(scene.fluid->tau, scene.fluid->porosity_lookup) *
          scene.fluid->dx;
    try {
      out.push_back(build_shape(p, shape_voxel_spacing(p, scene.fluid)));
    } catch (const ShapeError& e) {
      // Errors found while reading a file already name it; the others get the shape's place.
      const std::string what = e.what();
      if (what.rfind(scene.file, 0) == 0) throw SceneError(what);
      throw SceneError(scene.file + ": shapes[" + std::to_string(i) + "] '" + p.name +
                       "': " + what);
    }
  }
  return out;
}

}  // namespace lbdem
