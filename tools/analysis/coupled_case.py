"""Runs one coupled scene through the real entry point and reads what it wrote.

    mpirun -np A fluid_app scene.yaml : -np B dem_app scene.yaml

The DEM side writes <dem.output.directory>/<name>_bodies.csv (one row per body and output
time, see dem_app/coupling/body_trace.hpp); the directory is relative to the scene file.
"""
import csv
import os
import shutil
import subprocess
import time

import yaml


def mpirun():
    exe = shutil.which("mpirun") or "mpirun"
    return [exe, "--oversubscribe", "--allow-run-as-root"]


def run(build, scene, fluid_ranks=1, dem_ranks=1, extra_env=None, timeout=1800, replay=None):
    """Launches the case; returns (wall seconds, combined output). Raises on failure."""
    env = dict(os.environ)
    env.update({"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"})
    env.update(extra_env or {})
    fluid = os.path.abspath(os.path.join(build, "fluid_app", "fluid_app"))
    dem = os.path.abspath(os.path.join(build, "dem_app", "dem_app"))
    scene = os.path.abspath(scene)
    cmd = mpirun() + ["-np", str(fluid_ranks), fluid, scene, ":", "-np", str(dem_ranks), dem, scene]
    start = time.monotonic()
    # Run from the scene's folder, so output paths mean the same place whether a build resolves
    # them against the scene file (current) or the working directory (older fluid_app).
    proc = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          text=True, timeout=timeout, cwd=os.path.dirname(scene))
    wall = time.monotonic() - start
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}):\n{proc.stdout[-4000:]}")
    return wall, proc.stdout


def scene_info(scene):
    with open(scene) as f:
        s = yaml.safe_load(f)
    out = s.get("dem", {}).get("output", {}).get("directory", ".")
    directory = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(scene)), out))
    return s, os.path.join(directory, s["name"] + "_bodies.csv")


def fluid_series_path(scene):
    """<fluid.output.directory>/<name>_series.csv (domain means, the README)."""
    s, _ = scene_info(scene)
    out = s["fluid"]["output"]["directory"]
    directory = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(scene)), out))
    return os.path.join(directory, s["name"] + "_series.csv")


def read_series(path):
    """List of rows (dicts of floats) of the fluid's domain-mean CSV."""
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def read_trace(path):
    """{body id: list of rows (dicts of floats)} sorted by time."""
    bodies = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            r = {k: float(v) for k, v in row.items()}
            bodies.setdefault(int(r["id"]), []).append(r)
    return bodies
