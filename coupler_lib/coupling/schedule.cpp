#include "coupler_lib/coupling/schedule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "coupler_lib/errors.hpp"
#include "coupler_lib/scene/dem_time_step.hpp"

namespace lbdem {

namespace {

// Relative slack so that a ratio computed as 9.999999999999998 counts as 10.
constexpr double kSlack = 1e-9;

std::int64_t ceil_ratio(double a, double b) {
  return static_cast<std::int64_t>(std::ceil(a / b * (1 - kSlack)));
}

// A cadence in simulated seconds as a whole number of exchange intervals (at least one).
std::int64_t cadence(double seconds, double dt, int exchange_interval) {
  if (seconds <= 0) return 0;
  const double exchanges = seconds / (dt * exchange_interval);
  return std::max<std::int64_t>(1, std::llround(exchanges)) * exchange_interval;
}

}  // namespace

std::int64_t step_count(double end, double dt) {
  return std::max<std::int64_t>(1, ceil_ratio(end, dt));
}

int dem_substeps(double dt_fluid, double dt_dem) {
  if (dt_dem >= dt_fluid) return 1;
  const std::int64_t n = ceil_ratio(dt_fluid, dt_dem);
  if (n > std::numeric_limits<int>::max())
    throw SceneError("DEM step " + std::to_string(dt_dem) + " s is too small for fluid step " +
                     std::to_string(dt_fluid) + " s");
  return static_cast<int>(std::max<std::int64_t>(n, 1));
}

Schedule make_schedule(const Scene& scene, double dt_fluid, double dt_dem) {
  Schedule s;
  const bool fluid = scene.fluid.has_value(), dem = scene.dem.has_value();
  if (fluid && !(dt_fluid > 0))
    throw SceneError(scene.file + ": the fluid time step must be > 0, got " +
                     std::to_string(dt_fluid));
  if (dem && !(dt_dem > 0))
    throw SceneError(scene.file + ": the DEM time step must be > 0, got " + std::to_string(dt_dem));
  if (fluid) {
    s.dt = dt_fluid;
    if (dem) {
      s.dem_substeps = dem_substeps(dt_fluid, dt_dem);
      s.dt_dem = dt_fluid / s.dem_substeps;
    }
  } else {
    s.dt = dt_dem;
    s.dt_dem = dt_dem;
    s.dem_substeps = 1;
  }
  s.steps = step_count(scene.time.end, s.dt);
  s.exchange_interval = scene.coupling.exchange_interval;
  s.output_interval = cadence(scene.coupling.output_interval, s.dt, s.exchange_interval);
  s.checkpoint_interval = cadence(scene.coupling.checkpoint_interval, s.dt, s.exchange_interval);
  if (fluid && dem)
    s.rebalance_interval = cadence(scene.fluid->rebalance_interval, s.dt, s.exchange_interval);
  return s;
}

Schedule coupled_schedule(const Scene& scene, const std::vector<Shape>& shapes) {
  if (!scene.fluid || !scene.dem)
    throw SceneError(scene.file + ": a coupled run needs both a fluid and a dem section");
  return make_schedule(scene, scene.fluid->units.dt,
                       dem_time_step(*scene.dem, shapes, scene.bodies));
}

}  // namespace lbdem
