"""The resolved scene, read exactly as the programs read it (docs/user-guide.md, "The resolved
scene as JSON").

A tool never parses a scene's YAML to get values: PyYAML reads YAML 1.1, in which `1e-06` is a
string, and it knows no defaults. It asks the program instead:

    fluid_app --check --json scene.yaml

which validates the scene as a run would and prints every key with its default filled in (SI
units), the derived lattice numbers (dx, dt, tau, nu_lattice, cells), the schedule (steps,
substeps), the shapes and every body after generators and files are expanded. Tools may still
write scenes with PyYAML.

The build folder is the `build` argument, else $LBDEM_BUILD, else build/ at the top of the
repository.
"""
import json
import os
import subprocess

from . import run

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


class SceneError(ValueError):
    """The programs refused the scene; the message is theirs (file, key, what was expected)."""


def default_build():
    return os.environ.get("LBDEM_BUILD") or os.path.join(REPO, "build")


def use_build(build):
    """Makes `build` the default of this process (for tools given --build)."""
    os.environ["LBDEM_BUILD"] = os.path.abspath(build)


def program(build=None):
    """The fluid_app of the build: it prints the same JSON as dem_app (tested in ctest) and is
    built in every configuration."""
    path = os.path.join(os.path.abspath(build or default_build()), "fluid_app", "fluid_app")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path} not found: build the project first (cmake --build "
                                f"build --target fluid_app) or pass the build folder "
                                f"(--build or $LBDEM_BUILD)")
    return path


_cache = {}


def resolve(build, path):
    """The whole resolved scene of `path` as a dict: format, version, file, hash, coupled,
    scene (the keys, nested as in the YAML), derived (fluid, dem, schedule, bodies), shapes,
    bodies. Cached per file and modification time. Raises SceneError when the programs refuse
    the scene."""
    path = os.path.abspath(path)
    exe = program(build)
    key = (exe, path, os.stat(path).st_mtime_ns)
    if key not in _cache:
        proc = subprocess.run([exe, "--check", "--json", path], capture_output=True, text=True,
                              env=run.environment(), cwd=os.path.dirname(path))
        if proc.returncode != 0:
            raise SceneError(proc.stderr.strip() or f"{exe} --check --json {path} failed "
                             f"({proc.returncode})")
        _cache[key] = json.loads(proc.stdout)
    return _cache[key]


def load(path, build=None):
    """The scene's keys with their defaults (resolve(...)["scene"]), nested as in the YAML:
    load(p)["fluid"]["viscosity"] is a float whatever way the file spells it."""
    return resolve(build, path)["scene"]
