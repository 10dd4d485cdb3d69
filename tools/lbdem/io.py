"""Reading a run's scene and outputs (docs/user-guide.md: "Scene files", body output, fluid
output).

Paths in a scene are relative to the scene file's folder. A coupled run writes
  <dem.output.directory>/<name>_bodies.csv   one row per body and output time
                                             (time,id,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,fx..tz)
  <dem.output.directory>/<name>_bodies.h5    one group per snapshot (position, orientation, ...)
  <fluid.output.directory>/<name>_series.csv the fluid's domain means (time_s, mean_uz_m_s, ...)
  <dem.output.directory>/<name>_momentum.csv the momentum audit of a triply periodic run
                                             (fluid_p*, bodies_p*, applied_p*, N s)
"""
import csv
import os

import numpy as np

from . import scene as scene_json


def load_scene(path, build=None):
    """The scene's resolved keys, defaults filled in, as the programs read them (scene.py)."""
    return scene_json.load(path, build)


def read_scene_yaml(path):
    """A scene as written, only to write a variant of it (never to read values: YAML 1.1 reads
    `1e-06` as a string and knows no defaults; values come from load_scene)."""
    import yaml
    with open(path) as f:
        return yaml.safe_load(f)


def resolve(scene_path, path):
    """A path of the scene, relative to the scene file's folder when relative."""
    return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(scene_path)), path))


def dem_output_dir(scene_path, scene=None):
    s = scene or load_scene(scene_path)
    return resolve(scene_path, s.get("dem", {}).get("output", {}).get("directory", "."))


def summary_path(scene_path, side, scene=None):
    """The run summary of `side` ("fluid" or "dem"), where the programs write it
    (coupler_lib/coupling/run_summary.cpp): in dem.output.directory, or in fluid.output.directory
    for a scene without bodies."""
    s = scene or load_scene(scene_path)
    if "dem" in s:
        folder = dem_output_dir(scene_path, s)
    else:
        folder = resolve(scene_path, s["fluid"].get("output", {}).get("directory", "."))
    return os.path.join(folder, f"{s['name']}_{side}_summary.json")


def trace_path(scene_path, scene=None):
    s = scene or load_scene(scene_path)
    return os.path.join(dem_output_dir(scene_path, s), s["name"] + "_bodies.csv")


def bodies_h5_path(scene_path, scene=None):
    s = scene or load_scene(scene_path)
    return os.path.join(dem_output_dir(scene_path, s), s["name"] + "_bodies.h5")


def momentum_path(scene_path, scene=None):
    s = scene or load_scene(scene_path)
    return os.path.join(dem_output_dir(scene_path, s), s["name"] + "_momentum.csv")


def series_path(scene_path, scene=None):
    s = scene or load_scene(scene_path)
    out = s.get("fluid", {}).get("output", {}).get("directory", ".")
    return os.path.join(resolve(scene_path, out), s["name"] + "_series.csv")


def read_rows(path):
    """List of rows (dicts of floats) of a numeric CSV."""
    with open(path) as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def write_rows(path, rows):
    """Writes a list of dicts (one per row, the first row's keys as header) to a CSV, creating
    its folder, and says where."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {path}")


def read_trace_by_body(path):
    """{body id: list of rows (dicts of floats)} in time order."""
    bodies = {}
    for r in read_rows(path):
        bodies.setdefault(int(r["id"]), []).append(r)
    return bodies


class Trace:
    """The body trace as arrays: time (T,), id (N,), and per column an array (T, N) sorted by id.

    Only output times at which every body has a row are kept (a run cut short may end with a
    partial time)."""

    def __init__(self, path):
        data = np.genfromtxt(path, delimiter=",", names=True)
        data = np.atleast_1d(data)
        times, inverse = np.unique(data["time"], return_inverse=True)
        ids = np.unique(data["id"]).astype(int)
        count = np.bincount(inverse, minlength=len(times))
        full = count == len(ids)
        self.id = ids
        col = np.searchsorted(ids, data["id"].astype(int))
        self.columns = {}
        for name in data.dtype.names:
            if name in ("time", "id"):
                continue
            a = np.full((len(times), len(ids)), np.nan)
            a[inverse, col] = data[name]
            self.columns[name] = a[full]
        self.time = times[full]

    def __getitem__(self, name):
        return self.columns[name]

    def vectors(self, prefix):
        """(T, N, 3) array of the columns prefix+x, y, z (e.g. 'v' -> vx, vy, vz; '' -> x, y, z)."""
        return np.stack([self.columns[prefix + c] for c in "xyz"], axis=-1)

    def quaternions(self):
        return np.stack([self.columns["q" + c] for c in "wxyz"], axis=-1)


def read_series(path):
    """A numeric CSV with a header (the fluid's domain means, the momentum audit) as
    {column: array}."""
    data = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True))
    return {name: np.asarray(data[name]) for name in data.dtype.names}


def read_bodies_h5(path):
    """Snapshots of the body HDF5 output: list of dicts (time, position, orientation, velocity,
    angular_velocity, id, shape), in time order."""
    import h5py
    out = []
    with h5py.File(path, "r") as f:
        for name in sorted(k for k in f if k.startswith("snapshot_")):
            g = f[name]
            snap = {k: g[k][()] for k in ("position", "orientation", "velocity",
                                          "angular_velocity", "id", "shape")}
            snap["id"] = snap["id"].reshape(-1)
            snap["shape"] = snap["shape"].reshape(-1)
            snap["time"] = float(g.attrs["time"])
            out.append(snap)
    return out


def write_bodies_csv(path, position, orientation=None, comment=""):
    """A bodies file for the scene key `bodies: [{file: ...}]` (docs/study.md): columns x, y, z and
    optionally qw, qx, qy, qz, full precision."""
    cols = ["x", "y", "z"]
    parts = [np.asarray(position, float)]
    if orientation is not None:
        cols += ["qw", "qx", "qy", "qz"]
        parts.append(np.asarray(orientation, float))
    table = np.hstack(parts)
    with open(path, "w") as f:
        for line in comment.splitlines():
            f.write("# " + line + "\n")
        f.write(",".join(cols) + "\n")
        for row in table:
            f.write(",".join(repr(float(v)) for v in row) + "\n")


def write_bodies_h5(path, position, orientation=None, velocity=None, angular_velocity=None,
                    density=None, shape=None, comment=""):
    """A bodies file in HDF5 (docs/study.md, "Bodies from a file"): one float64 dataset per
    field at the root, one row per body (position N x 3 m, orientation N x 4 w x y z, velocity
    N x 3 m/s, angular_velocity N x 3 rad/s, density N kg/m^3), shape N variable-length strings;
    each with a `units` attribute, the comment as the file's `comment` attribute. Fields left
    None are not written (the scene entry's keys or the defaults apply)."""
    import h5py
    fields = [("position", position, "m"), ("orientation", orientation, "1 (w, x, y, z)"),
              ("velocity", velocity, "m/s"), ("angular_velocity", angular_velocity, "rad/s"),
              ("density", density, "kg/m^3")]
    with h5py.File(path, "w") as f:
        for name, value, units in fields:
            if value is not None:
                f[name] = np.asarray(value, dtype=np.float64)
                f[name].attrs["units"] = units
        if shape is not None:
            f.create_dataset("shape", data=[str(s) for s in shape], dtype=h5py.string_dtype())
        if comment:
            f.attrs["comment"] = comment


def read_bodies_h5_file(path):
    """(positions (N, 3), orientations (N, 4) or None) of an HDF5 bodies file."""
    import h5py
    with h5py.File(path, "r") as f:
        return f["position"][()], (f["orientation"][()] if "orientation" in f else None)


def read_bodies_csv(path):
    """(positions (N, 3), orientations (N, 4) or None) of a bodies file ('#' lines skipped)."""
    with open(path) as f:
        lines = [line for line in f if line.strip() and not line.lstrip().startswith("#")]
    data = np.atleast_1d(np.genfromtxt(lines, delimiter=",", names=True))
    pos = np.stack([data[c] for c in "xyz"], axis=-1)
    q = None
    if "qw" in data.dtype.names:
        q = np.stack([data["q" + c] for c in "wxyz"], axis=-1)
    return pos, q
