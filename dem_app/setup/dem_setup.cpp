#include "dem_app/setup/dem_setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <unordered_map>

#include "coupler_lib/scene/scene_checks.hpp"
#include "dem_app/contact/contact_model.hpp"
#include "dem_app/setup/lubrication_setup.hpp"

namespace lbdem {

DemSetup make_dem_setup(const Scene& scene, std::vector<Shape> shapes, bool coupled) {
  if (!scene.dem) throw SceneError(scene.file + ": the scene has no 'dem' section");
  DemSetup s;
  s.file = scene.file;
  s.params = *scene.dem;
  s.shapes = std::move(shapes);
  s.bodies = scene.bodies;
  const auto box = dem_box(scene);
  if (!box)
    throw SceneError(scene.file + ": dem.box: required when the scene has no fluid section");
  s.box_lo = box->lo;
  s.box_hi = box->hi;
  if (coupled && s.params.buoyancy_fluid_density > 0)
    throw SceneError(scene.file +
                     ": dem.buoyancy_fluid_density: only for DEM-only scenes; in a coupled run "
                     "the fluid side supplies buoyancy");
  s.buoyancy_density =
      coupled ? (scene.fluid ? scene.fluid->density : 0.0) : s.params.buoyancy_fluid_density;
  // The lubrication correction adds its forces through the same fix external.
  s.external_loads = coupled || s.buoyancy_density > 0 || s.params.lubrication.enabled;
  return s;
}

namespace {

[[noreturn]] void fail(const DemSetup& s, const std::string& what) {
  throw SceneError(s.file + ": " + what);
}

}  // namespace

void validate_dem_setup(const DemSetup& s) {
  const auto& p = s.params;
  if (s.shapes.empty()) fail(s, "shapes: the scene defines no shapes, but DEM needs at least one");
  if (s.bodies.empty()) fail(s, "bodies: the scene has a dem section but no bodies");
  for (size_t i = 0; i < s.shapes.size(); ++i) {
    const auto& sh = s.shapes[i];
    const std::string where = "shapes[" + std::to_string(i) + "] '" + sh.name + "': ";
    if (sh.clump.centers.empty() || sh.clump.centers.size() != sh.clump.radii.size())
      fail(s, where + "the clump has no spheres (or radii and centres differ in number)");
    for (double r : sh.clump.radii)
      if (!(r > 0)) fail(s, where + "a clump sphere has a non-positive radius");
    if (!(sh.mass.volume > 0)) fail(s, where + "volume must be positive");
    // Sylvester's criterion: all leading minors positive.
    const Eigen::Matrix3d& in = sh.mass.inertia;
    if (!(in(0, 0) > 0 && in.topLeftCorner<2, 2>().determinant() > 0 && in.determinant() > 0))
      fail(s, where + "the inertia tensor is not positive definite");
  }
  for (int d = 0; d < 3; ++d)
    if (!(s.box_hi[d] > s.box_lo[d]))
      fail(s, std::string("dem.box: the box is empty along ") + axis_name(d));
  (void)make_contact_model(p.material, s.file);
  if (p.buoyancy_fluid_density > 0 && p.gravity == std::array<double, 3>{0, 0, 0})
    fail(s, "dem.buoyancy_fluid_density: buoyancy needs a non-zero dem.gravity");

  check_body_placement(s.file, s.shapes, s.bodies, s.box_lo, s.box_hi, p);
  if (!(dem_time_step(s) > 0)) fail(s, "dem.dt: the DEM time step must be positive");
  check_lubrication_step(s, dem_time_step(s));
}

double dem_time_step(const DemSetup& setup) {
  return dem_time_step(setup.params, setup.shapes, setup.bodies);
}

double largest_sphere_radius(const DemSetup& setup) {
  double r = 0;
  for (const auto& b : setup.bodies)
    for (double ri : setup.shapes[static_cast<size_t>(b.shape)].clump.radii) r = std::max(r, ri);
  return r;
}

double dem_neighbor_skin(const DemSetup& setup) {
  return setup.params.neighbor_skin > 0 ? setup.params.neighbor_skin
                                        : 0.5 * largest_sphere_radius(setup);
}

}  // namespace lbdem
