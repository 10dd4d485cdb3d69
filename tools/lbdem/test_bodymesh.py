"""Body surface meshes: shapes placed at the body poses, one triangle mesh per output time
(ctest tools_lbdem_py)."""
import os
import tempfile
import unittest
import xml.etree.ElementTree as ET

import h5py
import numpy as np
import yaml

from lbdem import bodymesh, io

HEADER = "time,id,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,fx,fy,fz,tx,ty,tz\n"


class BodyMesh(unittest.TestCase):
    def test_meshes_are_closed_and_sized(self):
        v, f = bodymesh.icosphere()
        self.assertEqual(len(f), 320)
        np.testing.assert_allclose(np.linalg.norm(v, axis=1), 1.0)
        for verts, tris in (bodymesh.icosphere(), bodymesh.box_mesh([1, 2, 3])):
            # Closed, consistently oriented: every edge is used once in each direction, and
            # the divergence theorem gives the enclosed volume.
            edges = {(a, b) for t in tris for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}
            self.assertTrue(all((b, a) in edges for a, b in edges))
        v, f = bodymesh.box_mesh([1, 2, 3])
        vol = np.sum(np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]]))) / 6
        self.assertAlmostEqual(vol, 6.0)

    def test_surfaces_follow_the_trace(self):
        with tempfile.TemporaryDirectory() as d:
            # A valid scene: the tools read it through fluid_app --check --json (lbdem/scene.py).
            scene = {"name": "s", "time": {"end": 0.5},
                     "fluid": {"domain": [1, 1, 1], "dx": 0.1, "viscosity": 1e-6,
                               "output": {"directory": ".", "series": {"interval": 1e-3}}},
                     "dem": {"periodic": "xyz", "output": {"directory": "."}},
                     "shapes": [{"name": "c", "kind": "cube", "edge": 0.1}],
                     "bodies": [{"file": "b.csv", "shape": "c", "density": 2500}]}
            path = os.path.join(d, "s.yaml")
            with open(path, "w") as f:
                yaml.safe_dump(scene, f)
            with open(os.path.join(d, "b.csv"), "w") as f:
                f.write("x,y,z\n0.2,0.2,0.5\n0.6,0.6,0.5\n")
            h = np.radians(45) / 2  # second cube turned 45 degrees about z
            with open(os.path.join(d, "s_bodies.csv"), "w") as f:
                f.write(HEADER)
                for t in (0.0, 0.5):
                    f.write(f"{t},0,0.2,0.2,{0.5 - t},0,0,-1,0,0,0,1,0,0,0,0,0,0,0,0,0\n")
                    f.write(f"{t},1,0.6,0.6,0.5,0,0,-2,0,0,0,{np.cos(h)},0,0,{np.sin(h)},"
                            "0,0,0,0,0,0\n")
            xdmf = bodymesh.write_surfaces(path)
            grids = ET.parse(xdmf).getroot().findall(".//Grid[@GridType='Uniform']")
            self.assertEqual(len(grids), 2)
            with h5py.File(os.path.join(d, "s_surfaces.h5")) as h5:
                self.assertEqual(h5["triangles"].shape, (24, 3))
                p = h5["t000001/points"][()]
                np.testing.assert_allclose(p[:8].mean(axis=0), [0.2, 0.2, 0.0], atol=1e-15)
                np.testing.assert_allclose(np.linalg.norm(p[:8] - [0.2, 0.2, 0.0], axis=1),
                                           np.sqrt(3) * 0.05)
                # The turned cube reaches 0.05 sqrt(2) along x.
                self.assertAlmostEqual(p[8:, 0].max() - 0.6, 0.05 * np.sqrt(2))
                np.testing.assert_array_equal(h5["t000001/vz"][()], [-1.0] * 8 + [-2.0] * 8)


class BodyOutput(unittest.TestCase):
    def test_reads_the_dem_snapshots(self):
        # The layout dem_app/body_output.cpp writes: one group per snapshot, a time attribute.
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
