// fluid_app: the lattice Boltzmann side of the co-simulation.
#include "coupler_lib/app/run_app.hpp"

int main(int argc, char** argv) {
  const lbdem::AppInfo info{"fluid", "fluid_app",
                            "D3Q19 lattice Boltzmann fluid with homogenized bodies"};
  return lbdem::run_app(
      argc, argv, info,
      [](lbdem::AppContext& ctx) {
        if (ctx.rank == 0)
          ctx.log->info("scene '{}' is valid:\n{}", ctx.scene.name,
                        lbdem::describe_resolved(ctx.scene));
      },
      [](lbdem::AppContext& ctx) {
        ctx.log->info("scene '{}' loaded", ctx.scene.name);
        return 0;
      });
}
