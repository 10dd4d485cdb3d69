// fluid_app: the lattice Boltzmann side of the co-simulation.
#include "coupler_lib/app/run_app.hpp"
#include "fluid_app/coupling/coupled_fluid.hpp"
#include "fluid_app/run/fluid_run.hpp"

int main(int argc, char** argv) {
  const lbdem::AppInfo info{"fluid", "fluid_app",
                            "D3Q19 lattice Boltzmann fluid with homogenized bodies"};
  return lbdem::run_app(
      argc, argv, info,
      [](lbdem::AppContext& ctx) {
        if (ctx.rank == 0)
          ctx.log->info("scene '{}' is valid:\n{}", ctx.scene.name,
                        lbdem::describe_resolved(ctx.scene));
        if (ctx.scene.fluid) lbdem::log_fluid_setup(ctx, *ctx.scene.fluid);
      },
      [](lbdem::AppContext& ctx) {
        if (ctx.scene.coupled()) return lbdem::run_coupled_fluid(ctx);
        return lbdem::run_fluid_scene(ctx);
      });
}
