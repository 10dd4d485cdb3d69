// dem_app: the discrete element side of the co-simulation (LAMMPS as a library). A scene
// without a fluid section runs here alone; see dem_app/run/dem_run.hpp.
#include "coupler_lib/app/run_app.hpp"
#include "coupler_lib/scene/shape_catalogue.hpp"
#include "dem_app/coupling/coupled_dem.hpp"
#include "dem_app/run/dem_run.hpp"

int main(int argc, char** argv) {
  const lbdem::AppInfo info{"dem", "dem_app", "rigid multi-sphere bodies and contacts (LAMMPS)"};
  return lbdem::run_app(
      argc, argv, info,
      [](lbdem::AppContext& ctx) {
        // The whole scene was checked at start-up, as fluid_app does; a fluid-only scene is
        // valid here too, it just gives dem_app nothing to do.
        if (!ctx.scene.dem) {
          if (ctx.rank == 0)
            ctx.log->info("scene '{}' is valid (it has no 'dem' section: run it with fluid_app)",
                          ctx.scene.name);
          return;
        }
        const auto setup = lbdem::make_dem_setup(ctx.scene, lbdem::build_scene_shapes(ctx.scene),
                                                 ctx.scene.coupled());
        lbdem::validate_dem_setup(setup);
        if (ctx.rank == 0)
          ctx.log->info("scene '{}' is valid:\n{}DEM: {}", ctx.scene.name,
                        lbdem::describe_resolved(ctx.scene), lbdem::describe_engine_inputs(setup));
      },
      [](lbdem::AppContext& ctx) {
        if (ctx.scene.coupled()) return lbdem::run_coupled_dem(ctx);
        if (ctx.scene.fluid)
          throw lbdem::SceneError(ctx.scene.file +
                                  ": the scene has a fluid section but no bodies: run it with "
                                  "fluid_app alone");
        return lbdem::run_dem_only(ctx);
      });
}
