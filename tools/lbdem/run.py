"""Launching runs through the real entry points (docs/user-guide.md: "Running").

    mpirun -np A fluid_app scene.yaml : -np B dem_app scene.yaml     (coupled, MPMD)

Runs start in the scene's folder; Open MPI is allowed to run as root and to oversubscribe (the
shared development machine has 2 cores).
"""
import hashlib
import os
import shutil
import subprocess
import time


def mpirun():
    """The launcher. --bind-to none: tools may run several jobs at once, and each mpirun binds
    its ranks to cores counting from core 0, so concurrent jobs would share the first cores."""
    exe = shutil.which("mpirun") or "mpirun"
    return [exe, "--oversubscribe", "--allow-run-as-root", "--bind-to", "none"]


def environment(extra=None):
    env = dict(os.environ)
    env.update({"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"})
    env.update(extra or {})
    return env


def build_id(build):
    """Digest of a build's two programs. Tools that resume (the study, the work-precision
    ladders) reuse a finished run only from the binaries that made it, so a rebuilt method never
    passes off an older method's results as its own."""
    h = hashlib.sha256()
    for exe in ("fluid_app", "dem_app"):
        with open(os.path.join(build, exe, exe), "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
    return h.hexdigest()[:12]


def coupled_command(build, scene, fluid_ranks=1, dem_ranks=1):
    fluid = os.path.abspath(os.path.join(build, "fluid_app", "fluid_app"))
    dem = os.path.abspath(os.path.join(build, "dem_app", "dem_app"))
    scene = os.path.abspath(scene)
    return mpirun() + ["-np", str(fluid_ranks), fluid, scene, ":", "-np", str(dem_ranks), dem,
                       scene]


def execute(cmd, scene, timeout=None, log=None, extra_env=None):
    """Runs cmd from the scene's folder; returns (wall seconds, output). Raises on failure. With
    `log`, the output also goes to that file as it comes."""
    start = time.monotonic()
    cwd = os.path.dirname(os.path.abspath(scene))
    if log:
        with open(log, "w") as out:
            proc = subprocess.run(cmd, env=environment(extra_env), stdout=out,
                                  stderr=subprocess.STDOUT, text=True, timeout=timeout, cwd=cwd)
        with open(log) as f:
            text = f.read()
    else:
        proc = subprocess.run(cmd, env=environment(extra_env), stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=timeout, cwd=cwd)
        text = proc.stdout
    wall = time.monotonic() - start
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}):\n{text[-4000:]}")
    return wall, text


def run(build, scene, fluid_ranks=1, dem_ranks=1, extra_env=None, timeout=1800, log=None):
    """Launches a coupled scene; returns (wall seconds, combined output). Raises on failure."""
    return execute(coupled_command(build, scene, fluid_ranks, dem_ranks), scene, timeout, log,
                   extra_env)


def bench_scene_copy(source_root, scene, folder, replace=None):
    """configs/bench/SCENE written into FOLDER for a test or a tool: the clump paths made
    absolute, the output in FOLDER/out, and each (old, new) of `replace` applied (an `old`
    that is not found raises: the bench scene changed). Returns the new scene's path."""
    with open(os.path.join(source_root, "configs", "bench", scene)) as f:
        text = f.read()
    pairs = [("../shapes/", os.path.join(os.path.abspath(source_root), "configs", "shapes") + "/"),
             ("../../runs/bench", "out")] + list(replace or [])
    for old, new in pairs:
        if old not in text:
            raise ValueError(f"configs/bench/{scene} no longer holds {old!r}")
        text = text.replace(old, new)
    path = os.path.join(folder, scene)
    with open(path, "w") as f:
        f.write(text)
    return path
