#include "dem_app/setup/lubrication_setup.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lbdem {

namespace {

LubricationLaw law_of(const DemSetup& setup) {
  const auto& l = setup.params.lubrication;
  return {l.viscosity, l.cutoff, l.min_gap};
}

}  // namespace

Lubrication make_lubrication(const DemSetup& setup, const std::vector<Shape>& shapes,
                             const std::vector<Shape>& lammps_shapes) {
  if (!setup.params.lubrication.enabled) return {};
  std::vector<std::int64_t> body;
  std::vector<double> radius;
  for (size_t b = 0; b < setup.bodies.size(); ++b) {
    const auto s = static_cast<size_t>(setup.bodies[b].shape);
    const auto& own = shapes[s].clump.radii;
    const size_t n = lammps_shapes[s].clump.radii.size();
    for (size_t k = 0; k < n; ++k) {
      body.push_back(static_cast<std::int64_t>(b));
      radius.push_back(k < own.size() ? own[k] : 0.0);
    }
  }
  std::vector<LubricationWall> walls;
  for (const auto& w : setup.params.walls)
    walls.push_back({w.axis, w.lower,
                     w.position.value_or(w.lower ? setup.box_lo[w.axis] : setup.box_hi[w.axis])});
  return Lubrication(law_of(setup), std::move(body), std::move(radius), std::move(walls),
                     dem_neighbor_skin(setup));
}

void check_lubrication_step(const DemSetup& setup, double dt) {
  if (!setup.params.lubrication.enabled) return;
  const LubricationLaw law = law_of(setup);
  for (size_t b = 0; b < setup.bodies.size(); ++b) {
    const auto& body = setup.bodies[b];
    const Shape& sh = setup.shapes[static_cast<size_t>(body.shape)];
    double c = 0;
    for (double r : sh.clump.radii) c += lubrication_resistance(law, r, 0.0, law.min_gap);
    const double rate = dt * c / (body.density * sh.mass.volume);
    if (rate > 1) {
      std::ostringstream m;
      m << setup.file << ": dem.lubrication.min_gap: " << law.min_gap
        << " m makes the correction too stiff for the DEM step on body " << b
        << " (dt c/m = " << rate << ", must stay below 1); raise min_gap or lower dem.dt";
      throw SceneError(m.str());
    }
  }
}

}  // namespace lbdem
