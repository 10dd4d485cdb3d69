#include "dem_app/run/dem_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include "coupler_lib/app/progress.hpp"
#include "coupler_lib/coupling/schedule.hpp"
#include "coupler_lib/geometry/display_surface.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/contact/contact_model.hpp"
#include "dem_app/output/body_output.hpp"

namespace lbdem {

namespace {

// A relative difference as a signed percentage with four decimals ("+0.0050 %").
std::string percent(double relative) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.4f %%", 100.0 * relative);
  return text;
}

}  // namespace

std::string describe_engine_inputs(const DemSetup& setup) {
  std::ostringstream s;
  const auto& m = setup.params.material;
  const ContactModel c = make_contact_model(m, setup.file);
  const double t_r = smallest_rayleigh_time(setup.params, setup.shapes, setup.bodies);
  size_t spheres = 0;
  for (const auto& b : setup.bodies)
    spheres += setup.shapes[static_cast<size_t>(b.shape)].clump.radii.size();
  s << setup.bodies.size() << " bodies, " << spheres << " clump spheres; E = " << m.young_modulus
    << " Pa, nu = " << m.poisson_ratio << ", mu = " << m.friction << ", e = " << m.restitution;
  if (c.undamped)
    s << " (no damping)";
  else
    s << " (LAMMPS damping tsuji parameter " << c.tsuji_parameter << ")";
  s << "; Rayleigh time " << t_r << " s, DEM dt " << dem_time_step(setup) << " s";
  if (const auto& l = setup.params.lubrication; l.enabled)
    s << "; lubrication correction: h_c " << l.cutoff << " m, h_min " << l.min_gap << " m, mu "
      << l.viscosity << " Pa s";
  for (const auto& sh : setup.shapes)
    s << "; shape '" << sh.name << "': " << sh.clump.radii.size() << " spheres, volume "
      << sh.mass.volume << " m^3 (fluid's reference lattice "
      << percent(sh.reference_volume / sh.mass.volume - 1) << ")";
  return s.str();
}

int run_dem_only(AppContext& ctx) {
  const Scene& scene = ctx.scene;
  DemSetup setup = make_dem_setup(scene, build_scene_shapes(scene), false);
  const auto& out = setup.params.output;
  std::filesystem::path dir(out.directory);
  if (dir.is_relative()) dir = std::filesystem::path(scene.file).parent_path() / dir;
  if (ctx.rank == 0) std::filesystem::create_directories(dir);
  setup.lammps_log = (dir / (scene.name + "_lammps.log")).string();
  validate_dem_setup(setup);
  if (ctx.rank == 0) ctx.log->info("DEM: {}", describe_engine_inputs(setup));

  std::vector<TriangleMesh> surfaces;
  if (out.surfaces) surfaces = display_surfaces(scene.shapes, setup.shapes);
  LammpsEngine engine(ctx.side_comm, std::move(setup));
  const double dt = engine.dt();
  const auto total = static_cast<long>(step_count(scene.time.end, dt));
  auto every = [dt](double interval) {
    return interval > 0 ? steps_between(interval, dt) : 0L;
  };
  const long snap_every = every(out.interval);
  const long energy_every = out.energy_interval > 0 ? every(out.energy_interval) : snap_every;

  std::unique_ptr<BodySnapshotWriter> snapshots;
  std::unique_ptr<EnergySeries> energy;
  if (snap_every > 0)
    snapshots = std::make_unique<BodySnapshotWriter>(dir.string(), scene.name, ctx.side_comm,
                                                     std::move(surfaces));
  if (energy_every > 0)
    energy = std::make_unique<EnergySeries>((dir / (scene.name + "_energy.csv")).string(),
                                            ctx.side_comm);
  // At the output cadence, and always at the end.
  auto emit = [&](long step) {
    const bool last = step == total;
    if (snapshots && (step % snap_every == 0 || last))
      snapshots->write(engine.owned_states(step), engine.time());
    if (energy && (step % energy_every == 0 || last))
      energy->write(engine.time(), engine.energies());
  };

  Progress progress(ctx.log, scene.time.progress_interval, scene.time.end);
  // The run is chunked at the output events; between them LAMMPS runs uninterrupted.
  // Progress is reported at least every 1000 steps.
  constexpr long kMaxChunk = 1000;
  long step = 0;
  emit(0);
  while (step < total) {
    long next = std::min(total, step + kMaxChunk);
    if (snap_every > 0) next = std::min(next, (step / snap_every + 1) * snap_every);
    if (energy_every > 0) next = std::min(next, (step / energy_every + 1) * energy_every);
    engine.run(next - step);
    step = next;
    emit(step);
    progress.update(step, engine.time());
  }
  if (ctx.rank == 0) {
    ctx.log->info("DEM run finished: {} steps, t = {} s", step, engine.time());
    if (snapshots)
      ctx.log->info(
          "bodies: {} ({} snapshots){}", snapshots->xdmf_path(), snapshots->snapshots(),
          snapshots->surfaces_path().empty() ? "" : ", surfaces: " + snapshots->surfaces_path());
    if (energy) ctx.log->info("energy: {}", energy->path());
  }
  return 0;
}

}  // namespace lbdem
