// dem_app: the discrete element side of the co-simulation (LAMMPS as a library).
#include "coupler_lib/app/run_app.hpp"

int main(int argc, char** argv) {
  const lbdem::AppInfo info{"dem", "dem_app", "rigid multi-sphere bodies and contacts (LAMMPS)"};
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
