#include "coupler_lib/scene/scene_checks.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "coupler_lib/scene/body_placement.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"

namespace lbdem {

double fluid_memory_bytes(const FluidParams& fluid, bool bodies) {
  const double cells = double(fluid.cells[0]) * fluid.cells[1] * fluid.cells[2];
  const double value = fluid.precision == Precision::float32 ? 4 : 8;
  return cells * (2 * 19 * value + (bodies ? 8 : 0));
}

double physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? double(pages) * double(page) : 0;
}

namespace {

std::string gib(double bytes) {
  std::ostringstream s;
  s.precision(3);
  s << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return s.str();
}

void check_memory(const Scene& scene, double memory_bytes) {
  if (!scene.fluid || !(memory_bytes > 0)) return;
  const double need = fluid_memory_bytes(*scene.fluid, !scene.bodies.empty());
  if (need > memory_bytes) {
    const auto& c = scene.fluid->cells;
    std::ostringstream m;
    m << scene.file << ": fluid: the lattice of " << c[0] << " x " << c[1] << " x " << c[2]
      << " cells needs at least " << gib(need) << " (" << (need / (double(c[0]) * c[1] * c[2]))
      << " B per cell) but the nodes of this job have " << gib(memory_bytes)
      << "; use a coarser fluid.dx, a smaller fluid.domain or precision: float";
    throw SceneError(m.str());
  }
}

// A body the lattice cannot see: thinner than one fluid cell along its thinnest axis of the
// shape frame. Its porosity would never reach the solid value, so it would feel no fluid.
// Judged on the true shape, before the shapes are built: a calibrated hydrodynamic radius
// (fluid.hydrodynamic_radius) moves the fluid's surface inward and would leave no solid.
void check_resolution(const Scene& scene) {
  if (!scene.coupled()) return;
  const double dx = scene.fluid->dx;
  for (size_t i = 0; i < scene.bodies.size(); ++i) {
    const int k = scene.bodies[i].shape;
    if (k < 0 || static_cast<size_t>(k) >= scene.shapes.size()) continue;
    const ShapeParams& sh = scene.shapes[static_cast<size_t>(k)];
    const double thinnest = (extents_are_semi_axes(sh.kind) ? 2 : 1) *
                            *std::min_element(sh.extents.begin(), sh.extents.end());
    if (thinnest < dx) {
      std::ostringstream m;
      m << scene.file << ": bodies: body " << i << " (shape '" << sh.name << "') is " << thinnest
        << " m thick, thinner than one fluid cell (fluid.dx = " << dx
        << " m): the fluid cannot resolve it; use a finer fluid.dx or a larger shape";
      throw SceneError(m.str());
    }
  }
}

// With a fluid, a shape's voxel spacing is also the spacing h of the porosity stencil, and the
// fluid's reference lattice has voxels of h / 2 holding the fill of a box h (shape.hpp): the
// nearest lookup reads the voxels at x + h c_i, two voxels per c_i, and the trilinear one
// averages those neighbours once for all (fluid_app/hlbm/reference_porosity.hpp). The method
// (the band calibration is measured on it) takes h = dx / 2; another voxel_size would silently
// change the stencil and the box, so it is refused.
void check_voxel_size(const Scene& scene) {
  if (!scene.fluid) return;
  const double h = 0.5 * scene.fluid->dx;
  for (size_t i = 0; i < scene.shapes.size(); ++i) {
    const ShapeParams& sh = scene.shapes[i];
    if (sh.voxel_size <= 0 || std::abs(sh.voxel_size - h) <= 1e-9 * h) continue;
    std::ostringstream m;
    m << scene.file << ": shapes[" << i << "] '" << sh.name << "': voxel_size: " << sh.voxel_size
      << " m, but with a fluid the voxel spacing is the porosity stencil's, half the fluid "
         "spacing (fluid.dx / 2 = "
      << h << " m); leave voxel_size out or give that value";
    throw SceneError(m.str());
  }
}

}  // namespace

void check_whole_scene(const Scene& scene, double memory_bytes) {
  check_memory(scene, memory_bytes);
  check_resolution(scene);
  check_voxel_size(scene);
  const std::vector<Shape> shapes = build_scene_shapes(scene);
  // Without a box the DEM's own setup refuses the scene with its message.
  if (const auto box = dem_box(scene))
    check_body_placement(scene.file, shapes, scene.bodies, box->lo, box->hi, *scene.dem);
}

std::optional<DemBox> dem_box(const Scene& scene) {
  if (!scene.dem) return std::nullopt;
  if (scene.dem->has_box) return DemBox{scene.dem->box_lo, scene.dem->box_hi};
  if (scene.fluid) return DemBox{{0, 0, 0}, scene.fluid->domain};
  return std::nullopt;
}

}  // namespace lbdem
