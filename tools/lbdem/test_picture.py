"""The run picture (picture.py) and reading the DEM's body snapshots (ctest tools_lbdem_py); the
picture itself is drawn by ctest tools_picture_pvbatch where ParaView is installed."""
import os
import tempfile
import unittest
from unittest import mock

import h5py
import numpy as np
import yaml

from lbdem import io, picture


def write_scene(d):
    # A valid scene: the tools read it through fluid_app --check --json (lbdem/scene.py).
    scene = {"name": "s", "time": {"end": 0.5},
             "fluid": {"domain": [1, 1, 1], "dx": 0.1, "viscosity": 1e-6,
                       "output": {"directory": ".", "series": {"interval": 1e-3}}},
             "dem": {"periodic": "xyz", "output": {"directory": "out"}},
             "shapes": [{"name": "c", "kind": "cube", "edge": 0.1}],
             "bodies": [{"file": "b.csv", "shape": "c", "density": 2500}]}
    path = os.path.join(d, "s.yaml")
    with open(path, "w") as f:
        yaml.safe_dump(scene, f)
    with open(os.path.join(d, "b.csv"), "w") as f:
        f.write("x,y,z\n0.2,0.2,0.5\n0.6,0.6,0.5\n")
    return path


class Picture(unittest.TestCase):
    def test_surfaces_are_found_in_the_dem_output(self):
        with tempfile.TemporaryDirectory() as d:
            path = write_scene(d)
            self.assertEqual(picture.surfaces_path(path), os.path.join(d, "out", "s_surfaces.xdmf"))

    def test_without_paraview_says_how_to_get_it(self):
        with tempfile.TemporaryDirectory() as d:
            path = write_scene(d)
            said = []
            with mock.patch("shutil.which", return_value=None):
                self.assertIsNone(picture.render_png(path, said.append))
            self.assertIn("--with-paraview", said[0])

    def test_a_run_without_surfaces_is_refused(self):
        with tempfile.TemporaryDirectory() as d:
            path = write_scene(d)
            with mock.patch("shutil.which", return_value="/bin/true"):
                with self.assertRaisesRegex(FileNotFoundError, "dem.output.surfaces"):
                    picture.render_png(path)


class BodyOutput(unittest.TestCase):
    def test_reads_the_dem_snapshots(self):
        # The layout dem_app/output/body_output.cpp writes: one group per snapshot, a time attribute.
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "b.h5")
            with h5py.File(path, "w") as h5:
                for k, t in enumerate((0.0, 0.01)):
                    g = h5.create_group(f"snapshot_{k:06d}")
                    g["position"] = np.full((2, 3), t)
                    g["orientation"] = np.tile([1.0, 0, 0, 0], (2, 1))
                    g["velocity"] = g["angular_velocity"] = np.zeros((2, 3))
                    g["id"] = np.array([[0], [1]])
                    g["shape"] = np.array([[0], [0]], dtype=np.int32)
                    g.attrs["time"] = t
            snaps = io.read_bodies_h5(path)
            self.assertEqual([s["time"] for s in snaps], [0.0, 0.01])
            np.testing.assert_array_equal(snaps[1]["position"], np.full((2, 3), 0.01))
            np.testing.assert_array_equal(snaps[0]["id"], [0, 1])


if __name__ == "__main__":
    unittest.main()
