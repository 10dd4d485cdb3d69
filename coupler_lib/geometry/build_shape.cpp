#include "coupler_lib/geometry/build_shape.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/geometry/clump_generator.hpp"
#include "coupler_lib/geometry/clump_io.hpp"
#include "coupler_lib/geometry/mass_properties.hpp"
#include "coupler_lib/geometry/mesh_check.hpp"
#include "coupler_lib/geometry/offset_voxels.hpp"
#include "coupler_lib/geometry/stl_io.hpp"
#include "coupler_lib/geometry/voxelize.hpp"

namespace lbdem {

namespace {

// Default clump when the scene gives none: a sphere is its own exact clump; other shapes
// get a 100-sphere fill (the size of the paper's CLUMP-generated cube).
constexpr int kDefaultFillSpheres = 100;

// Empty voxel layers kept around the solid.
constexpr int kVoxelPad = 2;

// A clump file this far off the shape is almost surely at the wrong scale or for another
// shape: a single inscribed sphere in a cube misses 48 % of it, a clump at a tenth of the
// scale misses 99.9 %.
constexpr double kMaxFileClumpVolumeError = 0.8;

// Fewer solid voxels than this cannot give a meaningful volume or inertia.
constexpr std::size_t kMinSolidVoxels = 8;

// Largest distance from the centroid that any clump sphere reaches.
double clump_reach(const Clump& c, const Eigen::Vector3d& center) {
  double r = 0;
  for (std::size_t i = 0; i < c.size(); ++i)
    r = std::max(r, (c.centers[i] - center).norm() + c.radii[i]);
  return r;
}

std::string no_solid_left(const ShapeParams& p, double offset) {
  std::ostringstream s;
  s << p.where << ": shape '" << p.name << "': the fluid's surface moved inward by " << offset
    << " m (the band's hydrodynamic radius calibration, fluid.hydrodynamic_radius) leaves no "
       "solid; use a finer fluid.dx or fluid.hydrodynamic_radius: nominal";
  return s.str();
}

}  // namespace

ShapeParams scaled_params(const ShapeParams& p, double factor) {
  ShapeParams q = p;
  q.size *= factor;
  for (double& e : q.extents) e *= factor;
  q.scale *= factor;
  return q;
}

ShapeParams offset_params(const ShapeParams& p, double offset) {
  if (!offset_is_a_parameter(p.kind))
    throw std::logic_error("offset_params: only spheres, cubes and cuboids");
  if (offset == 0) return p;
  ShapeParams q = p;
  // size is a diameter or an edge; extents are edges (cube, cuboid) or semi-axes (sphere).
  const bool semi_axes = extents_are_semi_axes(p.kind);
  q.size -= 2 * offset;
  for (double& e : q.extents) e -= semi_axes ? offset : 2 * offset;
  if (!(*std::min_element(q.extents.begin(), q.extents.end()) > 0))
    throw ShapeError(no_solid_left(p, offset));
  return q;
}

Shape build_shape(const ShapeParams& p, double h) {
  Shape shape;
  shape.name = p.name;
  SolidGeometry solid = [&] {
    try {
      return make_solid(p);
    } catch (const ShapeError& e) {
      throw ShapeError(p.where + ": shape '" + p.name + "': " + e.what());
    }
  }();
  Voxels vox = voxelize(solid, h, kVoxelPad);
  shape.mass = mass_properties(solid);
  shape.voxel_spacing = h;
  if (vox.count() < kMinSolidVoxels) {
    std::ostringstream s;
    s << p.where << ": shape '" << p.name << "': only " << vox.count()
      << " voxel centres lie inside the shape at voxel spacing " << h
      << " m; the spacing must be well below the shape size (" << p.size << " m)";
    throw ShapeError(s.str());
  }
  const Eigen::Vector3d c = shape.mass.centroid;

  Clump clump;  // input frame
  const auto& cp = p.clump;
  try {
    if (cp.source == ClumpSource::file) {
      clump = translated(read_clump(cp.file, cp.scale), -c);
      shape.clump_source = "file " + cp.file;
    } else if (cp.source == ClumpSource::surface) {
      clump = surface_clump(solid, vox, {cp.grid, cp.radius_ratio, cp.center_sphere});
      shape.clump_source = "surface grid=" + std::to_string(cp.grid) +
                           " radius_ratio=" + std::to_string(cp.radius_ratio);
    } else if (cp.source == ClumpSource::fill || p.kind != ShapeKind::sphere) {
      const int n = cp.source == ClumpSource::fill ? cp.spheres : kDefaultFillSpheres;
      clump = fill_clump(solid, vox, {n});
      shape.clump_source = "fill spheres=" + std::to_string(n);
    } else {
      clump.centers.push_back(Eigen::Vector3d::Zero());
      clump.radii.push_back(p.size / 2);
      shape.clump_source = "exact sphere";
    }
  } catch (const ShapeError& e) {
    throw ShapeError(p.where + ": shape '" + p.name + "': clump: " + e.what());
  }
  shape.clump_quality = clump_quality(clump, vox);
  const double reach = clump_reach(clump, c);
  const double solid_radius = bounding_radius(vox, c);
  const bool too_big = reach > 1.1 * solid_radius + 2 * h;
  if (cp.source == ClumpSource::file &&
      (too_big || shape.clump_quality.volume_error > kMaxFileClumpVolumeError)) {
    std::ostringstream s;
    s << p.where << ": shape '" << p.name << "': clump file " << cp.file
      << " does not fit the shape: ";
    if (too_big)
      s << "its spheres reach " << reach << " m from the centroid, the shape only " << solid_radius
        << " m";
    else
      s << "it misses " << shape.clump_quality.volume_error << " of the shape volume";
    s << "; check clump.scale (now " << cp.scale << ")";
    throw ShapeError(s.str());
  }
  shape.clump = translated(std::move(clump), c);
  // The fluid's reference lattice (shape.hpp): voxels of h / 2 holding the fill of a box of
  // side h, of the true solid or of the scaled and offset one the fluid sees, centred on that
  // solid's centroid; its bounding radius sets which fluid ranks receive the body.
  const double r = h / 2;
  Voxels reference;
  Eigen::Vector3d cs = c;
  if (p.hydrodynamic_scale == 1 && p.hydrodynamic_offset == 0) {
    reference = voxelize(solid, r, kVoxelPad);
  } else {
    const ShapeParams sp = scaled_params(p, p.hydrodynamic_scale);
    const double offset = p.hydrodynamic_offset;
    if (offset == 0 || offset_is_a_parameter(p.kind)) {
      const SolidGeometry scaled_solid = make_solid(offset == 0 ? sp : offset_params(sp, offset));
      reference = voxelize(scaled_solid, r, kVoxelPad);
      cs = mass_properties(scaled_solid).centroid;
    } else {
      // The parallel body lies in the frame of the solid it is taken from, so it is centred
      // on that solid's centroid (its own centroid differs for a shape without symmetry).
      const SolidGeometry scaled_solid = make_solid(sp);
      if (!((scaled_solid.upper() - scaled_solid.lower()).minCoeff() > 2 * offset))
        throw ShapeError(no_solid_left(p, offset));
      reference = voxelize_offset(scaled_solid, offset, r, kVoxelPad);
      cs = mass_properties(scaled_solid).centroid;
    }
    if (reference.count() == 0) throw ShapeError(no_solid_left(p, offset));
  }
  reference = box_averaged(std::move(reference));
  shape.reference_volume = mass_properties(reference).volume;
  shape.bounding_radius = bounding_radius(reference, cs);
  shape.voxels = translated(std::move(reference), cs);
  return shape;
}

}  // namespace lbdem
