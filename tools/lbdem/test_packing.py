"""The packing generator: no overlaps (spheres and cubes), the requested solid fraction, lattice
order gone, g(r) of a hard-body fluid (ctest tools_lbdem_py)."""
import math
import os
import tempfile
import unittest

import numpy as np

from lbdem import analysis, io, packing
from lbdem import scene as lbdem_scene


class Packing(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.p = packing.make_packing(64, 150, seed=11, d=3.5e-4, log=lambda _: None)

    def test_start_is_phi_04_without_overlaps(self):
        self.assertAlmostEqual(self.p.phi(), 0.4, places=12)
        self.assertEqual(self.p.overlaps(), (0, 0))

    def test_lattice_order_is_gone(self):
        # 1 on the simple cubic lattice; random phases give ~ sqrt(pi / 4N) = 0.11 for N = 64.
        self.assertAlmostEqual(packing.Packing(64, 0.4).order_parameter(), 1.0, places=9)
        self.assertLess(self.p.order_parameter(), 3 / math.sqrt(self.p.n))

    def test_scaled_packings(self):
        for phi in (0.05, 0.1, 0.2, 0.3):
            s = self.p.scaled(phi)
            self.assertAlmostEqual(s.phi(), phi, places=12)
            measured = s.n * (s.a**3) / s.box**3  # the cubes fill the same volume
            self.assertAlmostEqual(measured, phi, places=12)
            self.assertEqual(s.overlaps(), (0, 0))
        with self.assertRaises(ValueError):
            self.p.scaled(0.45)

    def test_radial_distribution(self):
        # No pair closer than d; beyond contact a hard-sphere fluid at phi 0.4 (contact value
        # ~2.4 by Carnahan-Starling), not lattice spikes: g stays below 4 and
        # averages to about 1 beyond contact.
        box = np.full(3, self.p.box)
        r, g = analysis.radial_distribution(self.p.x, box, bins=16)
        self.assertEqual(g[r < 0.95 * self.p.d].max(), 0.0)
        self.assertLess(g.max(), 4.0)
        self.assertAlmostEqual(g[r > self.p.d].mean(), 1.0, delta=0.3)

    def test_count_that_is_not_a_cube(self):
        p = packing.Packing(50, 0.4, 2.0)
        self.assertEqual(p.n, 50)
        self.assertAlmostEqual(p.phi(), 0.4, places=12)
        self.assertEqual(p.overlaps(), (0, 0))

    def test_written_file_reads_back(self):
        with tempfile.TemporaryDirectory() as d:
            s = self.p.scaled(0.1)
            for name, read in (("p.csv", io.read_bodies_csv), ("p.h5", io.read_bodies_h5_file)):
                path = os.path.join(d, name)
                s.save(path, packing.PHI_START)
                x, q = read(path)
                np.testing.assert_array_equal(x, s.x)
                np.testing.assert_array_equal(q, s.q)

    def test_programs_read_the_hdf5_file_as_the_csv_file(self):
        # Both formats give the programs the same bodies (fluid_app --check --json).
        s = self.p.scaled(0.1)
        bodies = {}
        with tempfile.TemporaryDirectory() as d:
            for name in ("p.csv", "p.h5"):
                s.save(os.path.join(d, name), packing.PHI_START)
                path = os.path.join(d, name + ".yaml")
                with open(path, "w") as f:
                    f.write(f"name: p\ntime: {{end: 0.01}}\n"
                            f"dem: {{periodic: xyz, box: {{lo: [0, 0, 0], hi: [{s.box!r}, "
                            f"{s.box!r}, {s.box!r}]}}}}\n"
                            f"shapes:\n- {{name: ball, kind: sphere, diameter: {s.d!r}}}\n"
                            f"bodies:\n- {{file: {name}, shape: ball, density: 2500}}\n")
                bodies[name] = lbdem_scene.resolve(None, path)["bodies"]
        self.assertEqual(len(bodies["p.h5"]), s.n)
        self.assertEqual(bodies["p.h5"], bodies["p.csv"])


if __name__ == "__main__":
    unittest.main()
