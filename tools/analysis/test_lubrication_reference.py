"""Checks Brenner's series against their known limits (docs/lubrication.md)."""
import math
import unittest

import lubrication_reference as r


class Brenner(unittest.TestCase):
    def test_wall_far_tends_to_faxen(self):
        # Far from the wall: 1 + (9/8) a / (a + h) to first order in a / (a + h).
        self.assertAlmostEqual(r.brenner_wall(100.0, 1.0), 1 + 9 / 8 / 101, delta=2e-4)

    def test_wall_near_tends_to_cooley_oneill(self):
        # a/h + (1/5) ln(a/h) + 0.971 (Cooley & O'Neill 1969).
        for h in (1e-2, 1e-3):
            near = 1 / h + 0.2 * math.log(1 / h) + 0.971
            self.assertAlmostEqual(r.brenner_wall(h, 1.0) / near, 1.0, delta=1e-4)

    def test_pair_near_tends_to_reynolds(self):
        # Two equal spheres, each at U: a/(2h) + (9/20) ln(a/h) + O(1).
        h = 1e-3
        lam = r.brenner_pair(h, 1.0)
        self.assertAlmostEqual(lam - (0.5 / h + 0.45 * math.log(1 / h)), 1.35, delta=0.02)

    def test_pair_far_tends_to_stokes(self):
        self.assertAlmostEqual(r.brenner_pair(1000.0, 1.0), 1.0, delta=2e-3)

    def test_correction_zero_at_cutoff_and_leading_term_below(self):
        self.assertEqual(r.correction(0.1, 1.0, 0.1, 1e-3, True), 0.0)
        self.assertAlmostEqual(r.correction(1e-3, 1.0, 0.1, 1e-4, True),
                               1e3 - 10 + 0.2 * math.log(100), places=9)


if __name__ == "__main__":
    unittest.main()
