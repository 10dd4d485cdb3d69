"""The packing generator: no overlaps (spheres and cubes), the requested solid fraction, lattice
order gone, g(r) of a hard-body fluid (ctest tools_lbdem_py)."""
import math
import os
import tempfile
import unittest

import numpy as np

from lbdem import analysis, geometry, io, packing
from lbdem import scene as lbdem_scene


def _turn(axis, angle):
    """Quaternion of a rotation by `angle` about a unit `axis`."""
    return np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * np.asarray(axis, float)])


class CubeOverlapTest(unittest.TestCase):
    """The generator's separating-axis test (geometry.boxes_separated) on cube pairs whose
    contact distance is known, against the normalised test (geometry.box_separation) and
    through the periodic box."""

    half = np.full(3, 0.5)  # unit cubes

    def separated(self, t, qa, qb):
        ra, rb = geometry.rotation_matrices(np.array([qa])), geometry.rotation_matrices(
            np.array([qb]))
        fast = bool(geometry.boxes_separated(np.array([t], float), ra, rb, self.half,
                                             self.half)[0])
        exact = float(geometry.box_separation(np.array([t], float), ra, rb, self.half,
                                              self.half)[0]) > 0
        self.assertEqual(fast, exact, f"offset {t}")
        return fast

    def test_known_contact_distances(self):
        one = [1.0, 0, 0, 0]
        z45 = _turn([0, 0, 1], math.pi / 4)
        y45 = _turn([0, 1, 0], math.pi / 4)
        cases = [  # (orientation a, orientation b, direction, contact distance)
            (one, one, [1, 0, 0], 1.0),  # face to face
            (z45, one, [1, 0, 0], 0.5 + math.sqrt(0.5)),  # edge of a to the face of b
            (z45, z45, [1, 1, 0], 1.0),  # face to face along the turned axes
            # Edge to edge: a's edge along z at x = +sqrt(1/2) and b's edge along y at
            # x = -sqrt(1/2), crossing: only the axis z x y separates them.
            (z45, y45, [1, 0, 0], math.sqrt(2.0)),
        ]
        for qa, qb, direction, contact in cases:
            n = np.asarray(direction, float) / np.linalg.norm(direction)
            self.assertTrue(self.separated((contact + 1e-6) * n, qa, qb))
            self.assertFalse(self.separated((contact - 1e-6) * n, qa, qb))

    def test_edge_edge_needs_the_cross_axis(self):
        # Just beyond the edge-edge contact no face axis separates the cubes.
        z45, y45 = _turn([0, 0, 1], math.pi / 4), _turn([0, 1, 0], math.pi / 4)
        t = np.array([[math.sqrt(2.0) + 0.01, 0, 0]])
        ra, rb = geometry.rotation_matrices(np.array([z45])), geometry.rotation_matrices(
            np.array([y45]))
        a, b = ra[0].T, rb[0].T
        faces = np.concatenate([a, b])
        proj = np.abs(faces @ a.T) @ self.half + np.abs(faces @ b.T) @ self.half
        self.assertTrue(np.all(np.abs(faces @ t[0]) <= proj))
        self.assertTrue(geometry.boxes_separated(t, ra, rb, self.half, self.half)[0])

    def test_random_pairs_agree_with_the_normalised_test(self):
        rng = np.random.default_rng(5)
        m = 4000
        t = rng.uniform(-1.8, 1.8, (m, 3))
        ra = geometry.rotation_matrices(geometry.random_quaternions(rng, m))
        rb = geometry.rotation_matrices(geometry.random_quaternions(rng, m))
        gap = geometry.box_separation(t, ra, rb, self.half, self.half)
        fast = geometry.boxes_separated(t, ra, rb, self.half, self.half)
        clear = np.abs(gap) > 1e-9
        self.assertGreater(np.count_nonzero(gap > 0), m // 10)
        self.assertGreater(np.count_nonzero(gap <= 0), m // 10)
        np.testing.assert_array_equal(fast[clear], gap[clear] > 0)

    def test_pairs_across_the_periodic_boundary(self):
        # Two aligned cubes 0.9 a apart through the face x = 0 of the box: both the exact check
        # and the generator's count see the overlap; 1.1 a apart the cubes are clear (the
        # spheres, d = 1.24 a, still overlap), 1.3 a apart both are.
        p = packing.Packing(27, 0.05)  # lattice spacing 2.19 d: room between the rows
        for gap, spheres, expected in ((0.9, 1, 1), (1.1, 1, 0), (1.3, 0, 0)):
            p.x[0] = [0.05 * p.a, p.spacing, p.spacing]
            p.x[1] = [p.box - (gap - 0.05) * p.a, p.spacing, p.spacing]
            p.q[:] = [1, 0, 0, 0]
            self.assertEqual(p.overlaps(), (spheres, expected))
            mv = packing._Moves(p, np.random.default_rng(0), cubes=True)
            self.assertEqual(list(mv.cube_counts()[:2]), [expected, expected])
            self.assertEqual(int(mv.cube_counts()[2:].sum()), 0)

    def test_small_box_counts_every_image(self):
        # 8 bodies: the box is narrower than two cube reaches, so a pair can be close through
        # two images at once; near_pairs lists both, and a body with its own image once.
        p = packing.Packing(8, 0.4)
        p.x[0], p.x[1] = [0.0, 0, 0], [0.5 * p.box, 0, 0]
        i, j, d = p.near_pairs(0.6 * p.box)
        np.testing.assert_allclose(sorted(d[(i == 0) & (j == 1), 0]), [-0.5 * p.box,
                                                                       0.5 * p.box])
        i, j, d = p.near_pairs(1.01 * p.box)
        self.assertEqual(np.count_nonzero((i == 0) & (j == 0)), 3)  # +-x, +-y, +-z once each


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

    def test_relaxed_at_the_target_phi(self):
        # Scaled from phi 0.4 to 0.2 every pair is at least (0.4 / 0.2)^(1/3) d = 1.26 d apart;
        # relaxed at 0.2 the pairs between d and 1.2 d of the hard-body fluid there come back,
        # each body has moved beyond its neighbour spacing, and nothing overlaps.
        s = self.p.scaled(0.2)
        box = np.full(3, s.box)

        def closest(x):
            return np.linalg.norm(geometry.pair_separations(x, box)[2], axis=-1).min() / s.d

        self.assertGreater(closest(s.x), 1.25)
        self.assertAlmostEqual(packing.relax_step(0.2), (math.pi / 1.2) ** (1 / 3) - 1)
        self.assertEqual(packing.relax_step(0.01), 0.5)
        self.assertEqual(packing.relax_step(0.5), 0.1)
        acceptance, rms = packing.relax(s, 300, 5, packing.relax_step(0.2), log=lambda _: None)
        self.assertAlmostEqual(s.phi(), 0.2, places=12)
        self.assertEqual(s.overlaps(), (0, 0))
        self.assertGreater(acceptance, 0.1)
        self.assertGreater(rms, 1.5)
        r = np.linalg.norm(geometry.pair_separations(s.x, box)[2], axis=-1) / s.d
        self.assertGreaterEqual(r.min(), 1.0)
        self.assertGreater(np.count_nonzero(r < 1.2), 0)

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
