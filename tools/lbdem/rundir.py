"""A finished (or stopped) run, opened from its scene file (docs/user-guide.md, "Opening a run
from a script"):

    from lbdem.rundir import Run
    run = Run("configs/demo/settling_cubes.yaml")
    run.summary("fluid")["per_step_s"], run.trace.vectors("v"), run.series()["mean_uz_m_s"]

Every path comes from the scene as the programs resolve it (io.py); nothing is parsed from
log lines.
"""
import glob
import json
import os

from . import io


class Run:
    def __init__(self, scene_path, build=None):
        self.scene_path = os.path.abspath(scene_path)
        self.scene = io.load_scene(self.scene_path, build)
        self.name = self.scene["name"]
        self.directory = io.dem_output_dir(self.scene_path, self.scene)
        self._trace = None

    def summary(self, side):
        """The run summary one program wrote at its end (`side`: "fluid" or "dem"): steps, how
        the run ended, wall time, time per step by part, per-rank counters, load imbalance."""
        with open(io.summary_path(self.scene_path, side, self.scene)) as f:
            return json.load(f)

    @property
    def trace(self):
        """The body trace as arrays (io.Trace: time (T,), id (N,), columns (T, N))."""
        if self._trace is None:
            self._trace = io.Trace(io.trace_path(self.scene_path, self.scene))
        return self._trace

    def series(self):
        """The fluid's domain means as {column: array}."""
        return io.read_series(io.series_path(self.scene_path, self.scene))

    def momentum(self):
        """The momentum audit of a triply periodic settling run as {column: array}."""
        return io.read_series(io.momentum_path(self.scene_path, self.scene))

    def body_snapshots(self):
        """The bodies' HDF5 snapshots (list of dicts of arrays, in time order)."""
        return io.read_bodies_h5(io.bodies_h5_path(self.scene_path, self.scene))

    def field_files(self):
        """The fluid's HDF5 field snapshots, in time order; open each with h5py.File."""
        out = self.scene.get("fluid", {}).get("output", {}).get("directory", ".")
        return sorted(glob.glob(os.path.join(io.resolve(self.scene_path, out),
                                             f"{self.name}_fields_*.h5")))
