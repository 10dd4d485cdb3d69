#!/usr/bin/env python3
"""Launch files for a coupled scene on a cluster (docs/user-guide.md, "Clusters").

    tools/cluster_launch.py SCENE --fluid A --dem B [--out DIR] [--time 24:00:00]
        [--ranks-per-node 64] [--build BUILD]

writes, next to each other in DIR (default: the scene's folder):

  <name>.multiprog   Slurm's --multi-prog table: ranks 0..A-1 run fluid_app, A..A+B-1 dem_app
  <name>.sbatch      a batch script that runs it with srun (SIGTERM before the time limit,
                     so both programs write a checkpoint and stop cleanly)

and prints the Open MPI MPMD line for the same job. Both programs must have the same scene;
the fluid ranks come first (the programs find their side from MPI_APPNUM under mpirun, from
their own name under srun --multi-prog).
"""
import argparse
import math
import os
import sys


def multiprog_table(fluid_app, dem_app, scene, fluid, dem):
    """Slurm's --multi-prog configuration: one line per rank range."""
    last_fluid = fluid - 1
    return (f"0-{last_fluid} {fluid_app} {scene}\n" if fluid > 1 else f"0 {fluid_app} {scene}\n") + (
        f"{fluid}-{fluid + dem - 1} {dem_app} {scene}\n" if dem > 1 else f"{fluid} {dem_app} {scene}\n")


def sbatch_script(name, table, fluid, dem, hours, ranks_per_node):
    ranks = fluid + dem
    nodes = max(1, math.ceil(ranks / ranks_per_node))
    return f"""#!/bin/bash
#SBATCH --job-name={name}
#SBATCH --ntasks={ranks}
#SBATCH --nodes={nodes}
#SBATCH --time={hours}
# SIGTERM 5 minutes before the limit: both programs agree on it at the next agreement step,
# write a checkpoint and end with status 0 (docs/reliability.md); resubmit with --restart.
#SBATCH --signal=TERM@300
# One rank per core, bound: the fluid ranks first (they need the memory bandwidth), then the
# DEM ranks.
srun --cpu-bind=cores --kill-on-bad-exit=1 --multi-prog {table}
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("--fluid", type=int, required=True, help="fluid_app ranks")
    ap.add_argument("--dem", type=int, required=True, help="dem_app ranks")
    ap.add_argument("--out", help="folder for the files (default: the scene's folder)")
    ap.add_argument("--time", default="24:00:00", help="Slurm time limit")
    ap.add_argument("--ranks-per-node", type=int, default=64)
    ap.add_argument("--build", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build"))
    args = ap.parse_args()
    if args.fluid < 1 or args.dem < 1:
        sys.exit("cluster_launch: --fluid and --dem must be at least 1")
    scene = os.path.abspath(args.scene)
    if not os.path.isfile(scene):
        sys.exit(f"cluster_launch: {args.scene}: no such scene file")
    name = os.path.splitext(os.path.basename(scene))[0]
    out = os.path.abspath(args.out or os.path.dirname(scene))
    os.makedirs(out, exist_ok=True)
    build = os.path.abspath(args.build)
    fluid_app = os.path.join(build, "fluid_app", "fluid_app")
    dem_app = os.path.join(build, "dem_app", "dem_app")
    table = os.path.join(out, name + ".multiprog")
    with open(table, "w") as f:
        f.write(multiprog_table(fluid_app, dem_app, scene, args.fluid, args.dem))
    batch = os.path.join(out, name + ".sbatch")
    with open(batch, "w") as f:
        f.write(sbatch_script(name, table, args.fluid, args.dem, args.time, args.ranks_per_node))
    print(f"Slurm: sbatch {batch}   (rank table {table})")
    print(f"Open MPI: mpirun --map-by core --bind-to core -np {args.fluid} {fluid_app} {scene} "
          f": -np {args.dem} {dem_app} {scene}")


if __name__ == "__main__":
    main()
