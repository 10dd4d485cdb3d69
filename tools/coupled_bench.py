#!/usr/bin/python3
"""coupled_bench: throughput of coupled runs against the fluid alone on the same lattice.

    /usr/bin/python3 tools/coupled_bench.py --build build [--quick] [--np-fluid 1 --np-dem 1]
                                            [--only cubes64_c100,fluid58] [--repeat N]

Runs the scenes of configs/bench/ through mpirun exactly as a user would
(mpirun -np A fluid_app s.yaml : -np B dem_app s.yaml; fluid-only scenes with fluid_app
alone), then prints one row per scene: MLUPS, the ratio to the fluid-only MLUPS of the same
lattice, and the wall time per step split into the parts both programs report at the end
of a coupled run (fluid: lattice, porosity + momentum exchange, exchange, idle; DEM: LAMMPS
with its substeps, exchange, idle) plus the DEM's clump-sphere steps per second.

Every figure comes from the run summaries both programs write at the end
(<name>_fluid_summary.json, <name>_dem_summary.json; docs/user-guide.md, "Run summary"), no
log line is parsed. MLUPS is the lattice cells times fluid rank 0's steps per second from its
first progress line to its last (the first progress interval is the warm-up: caches, first
embedding, LAMMPS set-up run); with fewer than two progress lines it falls back to the cells
over the sum of the fluid rank's per-step parts. The split is averaged over all steps of the
run. --quick runs the two small quick_* scenes for a smoke test (ctest checks that every
figure is printed, never a time). --repeat N runs the whole plan N times in turn (each coupled
scene right after its fluid-only reference, so each ratio compares runs minutes apart) and ends
with each coupled scene's median, smallest and largest ratio: on a shared machine one run's
ratio scatters by several per cent.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import io, run  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCH = os.path.join(ROOT, "configs", "bench")

# (scene, fluid-only reference scene); a reference of None marks a fluid-only scene.
FULL = [
    ("fluid58", None),
    ("cubes64_c27", "fluid58"),
    ("cubes64_c100", "fluid58"),
    ("cubes64_c100_particle_dt", "fluid58"),
    ("cubes64_c100_overlap", "fluid58"),
    ("cubes64_c489", "fluid58"),
    ("fluid72", None),
    ("cubes125_c27", "fluid72"),
    ("cubes125_c100", "fluid72"),
    ("cubes125_c489", "fluid72"),
    ("fluid135", None),
    ("spheres967", "fluid135"),
]
QUICK = [("quick_fluid29", None), ("quick_cubes8_c27", "quick_fluid29")]


def run_scene(args, name):
    scene = os.path.join(BENCH, name + ".yaml")
    fluid_app = os.path.join(args.build, "fluid_app", "fluid_app")
    dem_app = os.path.join(args.build, "dem_app", "dem_app")
    coupled = not name.startswith(("fluid", "quick_fluid"))
    cmd = run.mpirun() + ["-np", str(args.np_fluid), fluid_app, scene]
    if coupled:
        cmd += [":", "-np", str(args.np_dem), dem_app, scene]
    t0 = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=BENCH, env=run.environment())
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.stderr.write((p.stdout + p.stderr)[-4000:])
        raise SystemExit(f"coupled_bench: {' '.join(cmd)} failed with status {p.returncode}")
    resolved = io.load_scene(scene, args.build)
    summary = {}
    for side in ("fluid", "dem") if coupled else ("fluid",):
        with open(io.summary_path(scene, side, resolved)) as f:
            summary[side] = json.load(f)
    fluid = summary["fluid"]
    cells = int(sum(fluid["per_rank"]["cells"]["values"]))
    r = {"name": name, "cells": cells, "wall": wall, "coupled": coupled}
    part = fluid["per_step_s"]
    if coupled:
        dem = summary["dem"]
        r.update(lattice=part["lattice"], bodies=part["porosity + momentum exchange"],
                 f_exchange=part["exchange"], f_idle=part["idle"], dem=dem["per_step_s"]["DEM"],
                 substeps=int(dem["per_rank"]["substeps"]["values"][0]),
                 d_exchange=dem["per_step_s"]["exchange"], d_idle=dem["per_step_s"]["idle"],
                 spheres=int(sum(dem["per_rank"]["clump_spheres"]["values"])))
    # Fluid rank 0's steps per second after its first progress line (the first interval is
    # the warm-up); with fewer than two lines, the cells over the fluid's time per step.
    rate = fluid["per_rank"]["steps_per_s"]["values"][0]
    if rate > 0:
        r["mlups"], r["from"] = cells * rate * 1e-6, "progress"
    else:
        r["mlups"], r["from"] = cells / sum(part.values()) * 1e-6, "split"
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--np-fluid", type=int, default=1)
    ap.add_argument("--np-dem", type=int, default=1)
    ap.add_argument("--only", default="", help="comma-separated scene names")
    ap.add_argument("--repeat", type=int, default=1, help="runs of the whole plan, in turn")
    args = ap.parse_args()
    args.build = os.path.abspath(args.build)
    plan = QUICK if args.quick else FULL
    if args.only:
        keep = set(args.only.split(","))
        plan = [p for p in plan if p[0] in keep]
    env_note = os.uname().nodename
    print(f"# coupled_bench: {args.np_fluid} fluid rank(s) : {args.np_dem} DEM rank(s), "
          f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, host {env_note}, "
          f"load average {os.getloadavg()[0]:.1f}")
    print("# times in ms per fluid step; fluid: lattice, porosity + momentum exchange (bodies), "
          "exchange, idle; DEM: LAMMPS (substeps), exchange, idle; sphere-steps/s = clump "
          "spheres x substeps / LAMMPS time")
    print(f"# {'scene':<26} {'cells':>9} {'MLUPS':>7} {'/fluid':>7} | {'lattice':>8} "
          f"{'bodies':>8} {'exch':>6} {'idle':>6} | {'DEM':>8} {'sub':>4} {'exch':>6} "
          f"{'idle':>6} {'sph-steps/s':>11}")
    fluid_only = {}
    ratios = {}
    for _ in range(max(args.repeat, 1)):
        for name, ref in plan:
            run_and_print(args, name, ref, fluid_only, ratios)
    if args.repeat > 1:
        for name, rs in ratios.items():
            print(f"# {name}: / fluid-only over {len(rs)} runs: median "
                  f"{100 * statistics.median(rs):.1f}%, smallest {100 * min(rs):.1f}%, largest "
                  f"{100 * max(rs):.1f}%")


def run_and_print(args, name, ref, fluid_only, ratios):
    """Runs one scene and prints its row; a fluid-only scene's MLUPS becomes the reference of
    the coupled scenes after it, a coupled scene's ratio is added to `ratios`."""
    r = run_scene(args, name)
    if not r["coupled"]:
        fluid_only[name] = r["mlups"]
        print(f"  {name:<26} {r['cells']:>9} {r['mlups']:>7.2f} {'1':>7} |", flush=True)
        return
    if ref in fluid_only:
        ratios.setdefault(name, []).append(r["mlups"] / fluid_only[ref])
    ratio = f"{100 * r['mlups'] / fluid_only[ref]:.1f}%" if ref in fluid_only else "-"
    ms = lambda k: f"{1e3 * r[k]:.2f}"  # noqa: E731
    rate = r["spheres"] * r["substeps"] / r["dem"] if r["dem"] > 0 else 0.0
    print(f"  {name:<26} {r['cells']:>9} {r['mlups']:>7.2f} {ratio:>7} | {ms('lattice'):>8} "
          f"{ms('bodies'):>8} {ms('f_exchange'):>6} {ms('f_idle'):>6} | {ms('dem'):>8} "
          f"{r['substeps']:>4} {ms('d_exchange'):>6} {ms('d_idle'):>6} {rate:>11.3g}",
          flush=True)


if __name__ == "__main__":
    main()
