#!/usr/bin/python3
"""What each optional feature costs when on, and that a scene without it pays nothing
(docs/performance-features.md).

    tools/feature_cost.py --build build                   # every variant, 3 repeats
    tools/feature_cost.py --build build --cells 24 --steps 100 --repeats 1   # quick

One triply periodic lattice of N^3 cells (tau 0.6, water), run for a fixed number of steps in
variants that add one feature at a time to the plain fluid (stability watch off, no output):
the stability watch, series output, field output, the mean-velocity controller; then
coupled: one sphere at rest without gravity (bodies: porosity, loads, the DEM program), the
sphere spinning (rotation), falling under gravity (the compensating force of the settling
balance), body output every step, recording of every packet, and two spheres close enough to
touch (contacts). Each variant runs through the real entry point (`fluid_app s.yaml`, or
`mpirun -np 1 fluid_app s.yaml : -np 1 dem_app s.yaml`); the figure is the CPU time of all
processes (user + system, from the operating system's accounting of the finished children),
which load on a shared machine disturbs far less than wall time, and the best of --repeats.
Each variant runs at two step counts (--steps S and 3 S); the difference divided by 2 S is the
CPU per step with the start-up (MPI, LAMMPS, set-up, first touch) taken out.
The plain fluid is also compared with the kernel alone (`fluid_bench`, same size, same
precision) when that program is built.
"""
import argparse
import copy
import os
import re
import resource
import subprocess
import sys
import tempfile

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from lbdem import run  # noqa: E402

NU, TAU = 1.0e-6, 0.6


def plain(n, steps, dx=1.0e-4):
    dt = (TAU - 0.5) * dx * dx / (3 * NU)
    return {"name": "plain", "time": {"end": steps * dt, "progress_interval": 1000},
            "fluid": {"domain": [n * dx] * 3, "dx": dx, "viscosity": NU, "density": 1000,
                      "tau": TAU, "stability": {"interval": 0}}}


def coupled(s, n, dx=1.0e-4):
    s["dem"] = {"gravity": [0, 0, 0], "periodic": "xyz", "output": {"directory": "."}}
    s["shapes"] = [{"name": "sphere", "kind": "sphere", "diameter": n * dx / 4}]
    s["bodies"] = [{"shape": "sphere", "position": [n * dx / 2] * 3, "density": 2500}]
    return s


def variants(n, steps):
    """(name, what it adds, scene) in order; each coupled one adds to "bodies"."""
    dx = 1.0e-4
    dt = (TAU - 0.5) * dx * dx / (3 * NU)
    out = []

    def add(name, what, f, base=None):
        s = copy.deepcopy(base or plain(n, steps))
        s["name"] = name
        f(s)
        out.append((name, what, s))
        return s

    add("plain", "fluid alone: stability watch off, no output", lambda s: None)
    add("watch", "stability watch every 100 steps (the default)",
        lambda s: s["fluid"].pop("stability"))
    add("series", "series output (domain means) every 10 steps",
        lambda s: s["fluid"].update(output={"directory": ".", "series": {"interval": 10 * dt}}))
    add("fields", "field output (all fields, HDF5 + XDMF) every 50 steps",
        lambda s: s["fluid"].update(output={"directory": ".", "fields": {"interval": 50 * dt}}))
    add("controller", "mean-velocity controller (target 0)",
        lambda s: s["fluid"].update(mean_velocity_control={"target": [0, 0, 0]}))
    bodies = add("bodies", "one sphere d = N/4 at rest, no gravity (DEM program, porosity, loads)",
                 lambda s: coupled(s, n))
    add("rotation", "the sphere spinning (0.5 cells per step at its surface)",
        lambda s: s["bodies"][0].update(angular_velocity=[0, 0, 0.5 * dx / dt / (n * dx / 8)]),
        bodies)
    # A weak gravity keeps the falling sphere slow (lattice Mach < 0.1) over the run; at 9.81
    # m/s^2 this sphere (d = 10 cells at N = 40) would reach Mach ~ 0.9 and diverge.
    add("compensating", "gravity 0.2 m/s^2: the compensating force of the settling balance",
        lambda s: s["dem"].update(gravity=[0, 0, -0.2]), bodies)
    add("body_output", "body trace written every step",
        lambda s: s.update(coupling={"output_interval": dt}), bodies)
    add("recording", "every packet recorded to HDF5",
        lambda s: s.update(coupling={"record": "rec.h5"}), bodies)

    def two(s):
        d = n * dx / 4
        s["bodies"] = [{"shape": "sphere", "position": [n * dx / 2, n * dx / 2, z],
                        "density": 2500} for z in (n * dx / 2 - 0.52 * d, n * dx / 2 + 0.52 * d)]
    add("contacts", "two spheres a 0.04 d gap apart (contact detection, neighbour lists)", two,
        bodies)
    return out


def run_variant(build, scene, work):
    path = os.path.join(work, scene["name"] + ".yaml")
    with open(path, "w") as f:
        yaml.safe_dump(scene, f, sort_keys=False)
    if "dem" in scene:
        cmd = run.coupled_command(build, path)
    else:
        cmd = run.mpirun() + ["-np", "1", os.path.abspath(os.path.join(build, "fluid_app",
                                                                       "fluid_app")), path]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall, _ = run.execute(cmd, path, timeout=900)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def kernel_mlups(build, n):
    exe = os.path.join(build, "tools", "fluid_bench")
    if not os.path.exists(exe):
        return None
    p = subprocess.run(run.mpirun() + ["-np", "1", os.path.abspath(exe), "--sizes", str(n),
                                       "--seconds", "1.5"], env=run.environment(),
                       capture_output=True, text=True, timeout=300)
    m = re.search(r"double\s+\S+\s+([0-9.]+)", p.stdout)
    return float(m.group(1)) if m else None


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--cells", type=int, default=48, help="N: the lattice is N^3")
    ap.add_argument("--steps", type=int, default=400)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--only", nargs="+")
    args = ap.parse_args()
    rows = []
    long_run = 3 * args.steps
    with tempfile.TemporaryDirectory(prefix="lbdem_features_") as work:
        short = dict((v[0], v) for v in variants(args.cells, args.steps))
        for name, what, scene in variants(args.cells, long_run):
            if args.only and name not in args.only and name != "plain":
                continue
            c1, w1 = min((run_variant(args.build, short[name][2], work)
                          for _ in range(args.repeats)), key=lambda cw: cw[0])
            c2, w2 = min((run_variant(args.build, scene, work) for _ in range(args.repeats)),
                         key=lambda cw: cw[0])
            per_step = (c2 - c1) / (long_run - args.steps)
            rows.append((name, what, per_step, c1 - per_step * args.steps, w2))
            print(f"{name}: CPU {c1:.2f} s ({args.steps} steps), {c2:.2f} s ({long_run} steps): "
                  f"{1e3 * per_step:.3f} ms per step", flush=True)
    base = rows[0][2]
    cells = args.cells ** 3
    print(f"\n{args.cells}^3 cells; CPU of all processes (fluid_app + dem_app + mpirun), best of "
          f"{args.repeats}, per step from the difference of {args.steps} and {long_run} steps")
    print("| variant | adds | CPU per step (ms) | / plain | CPU us per cell update | start-up CPU (s) "
          "| wall, long run (s) |")
    print("|---|---|---|---|---|---|---|")
    for name, what, per_step, startup, wall in rows:
        print(f"| {name} | {what} | {1e3 * per_step:.3f} | {per_step / base:.3f} | "
              f"{1e6 * per_step / cells:.4f} | {startup:.2f} | {wall:.2f} |")
    k = kernel_mlups(args.build, args.cells)
    if k:
        print(f"\nkernel alone (fluid_bench --sizes {args.cells}, double): {k:.1f} MLUPS; plain "
              f"fluid_app: {cells / 1e6 / base:.1f} cell updates per CPU us")
    return 0


if __name__ == "__main__":
    sys.exit(main())
