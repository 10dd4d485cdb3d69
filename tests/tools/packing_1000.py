#!/usr/bin/python3
"""tools/make_packing.py on 1000 bodies at phi 0.3 (ctest tools_packing_1000), checked from the
files it writes, independently of the generator: no sphere or cube overlap at phi 0.4 and 0.3
(Packing.overlaps over every pair and image), the solid fraction of the box in the file header,
the lattice order gone, uniformly random orientations, g(r) of a fluid; and a spheres-only
packing whose contact value g(d+) is that of hard spheres at phi 0.4 (Carnahan-Starling).
Wall-clock times are printed by the tool, never checked."""
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from lbdem import geometry, io, packing  # noqa: E402

N, D = 1000, 3.5e-4


def make(out, *extra):
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "make_packing.py"), "--bodies",
                    str(N), "--diameter", repr(D), "--phi", "0.3", "--sweeps", "100", "--seed",
                    "2", "--out", out, *extra], check=True)


def read(path):
    """The packing in a bodies file, its box from the header line."""
    with open(path) as f:
        box = float(re.search(r"periodic box edge ([0-9.eE+-]+) m", f.read()).group(1))
    p = packing.Packing.__new__(packing.Packing)
    p.d, p.a, p.box = D, packing.CUBE_PER_SPHERE * D, box
    p.x, p.q = io.read_bodies_csv(path)
    p.spacing = box / math.ceil(round(N ** (1 / 3), 9))
    return p


class Packing1000(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        make(os.path.join(cls.tmp.name, "cubes"))
        make(os.path.join(cls.tmp.name, "spheres"), "--spheres-only")
        cls.p = {phi: read(os.path.join(cls.tmp.name, "cubes", f"packing_phi{phi:.3f}.csv"))
                 for phi in (0.4, 0.3)}

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_no_overlaps_and_the_solid_fraction(self):
        for phi, p in self.p.items():
            self.assertEqual(p.n, N)
            self.assertAlmostEqual(p.phi(), phi, places=6)
            self.assertTrue(np.all((p.x >= 0) & (p.x < p.box)))
            self.assertEqual(p.overlaps(), (0, 0))

    def test_lattice_order_is_gone(self):
        self.assertLess(self.p[0.3].order_parameter(), 3 / math.sqrt(N))

    def test_orientations_are_uniform(self):
        # Uniform rotations: every entry R_ij has mean 0 and mean square 1/3 (standard error
        # 0.009 and 0.018 for 1000 bodies).
        r = geometry.rotation_matrices(self.p[0.3].q)
        np.testing.assert_allclose(r.mean(axis=0), 0.0, atol=0.06)
        np.testing.assert_allclose((r**2).mean(axis=0), 1 / 3, atol=0.05)

    def test_radial_distribution_of_a_fluid(self):
        # No pair closer than d (1.1 d at phi 0.3, scaled), no lattice spikes, g about 1 from
        # 2 d on.
        p = self.p[0.4]
        r, g = p.radial_distribution(4 * D, 40)
        self.assertEqual(g[r < 0.95 * D].max(), 0.0)
        self.assertLess(g.max(), 4.0)
        self.assertAlmostEqual(g[r > 2 * D].mean(), 1.0, delta=0.1)
        s = (0.4 / 0.3) ** (1 / 3)
        r, g = self.p[0.3].radial_distribution(4 * D, 40)
        self.assertEqual(g[r < 0.95 * s * D].max(), 0.0)

    def test_hard_sphere_contact_value(self):
        # The spheres-only packing at phi 0.4 against Carnahan-Starling (3.70); the cubes
        # exclude many close pairs, so with them g(d+) is well below.
        spheres = read(os.path.join(self.tmp.name, "spheres", "packing_phi0.400.csv"))
        cs = packing.carnahan_starling_contact(0.4)
        self.assertEqual(spheres.overlaps()[0], 0)
        self.assertAlmostEqual(spheres.contact_value() / cs, 1.0, delta=0.1)
        self.assertLess(self.p[0.4].contact_value(), 0.75 * cs)


if __name__ == "__main__":
    unittest.main()
