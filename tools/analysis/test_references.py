"""Checks the reference formulas (tools/lbdem/references.py) against published numbers."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from lbdem import references as r  # noqa: E402


class References(unittest.TestCase):
    def test_sangani_acrivos_at_03(self):
        self.assertAlmostEqual(r.sangani_acrivos_k(0.3), 12.10, delta=0.01)

    def test_zick_homsy_agreement(self):
        self.assertAlmostEqual(r.sangani_acrivos_k(0.216), 7.442, delta=0.01)

    def test_hasimoto_low_at_03(self):
        self.assertAlmostEqual(r.hasimoto_k(0.3), 11.58, delta=0.02)

    def test_richardson_zaki_at_re_16_8(self):
        self.assertAlmostEqual(r.richardson_zaki_exponent(16.8), 3.356, delta=0.002)
        for phi, ratio in [(0.05, 0.842), (0.1, 0.702), (0.2, 0.473), (0.3, 0.302), (0.4, 0.180)]:
            self.assertAlmostEqual(r.richardson_zaki(phi, 16.8), ratio, delta=0.001)

    def test_exponent_correlations_limits(self):
        # Garside & Al-Dibouni: 5.1 at Re -> 0, 0.27 / 0.1 = 2.7 at Re -> infinity; Rowe: 4.7 and
        # 0.41 / 0.175; both near Richardson-Zaki's 3.36 at the study's Re = 16.8.
        self.assertAlmostEqual(r.garside_al_dibouni_exponent(1e-9), 5.1, delta=1e-6)
        self.assertAlmostEqual(r.garside_al_dibouni_exponent(1e12), 2.7, delta=1e-3)
        self.assertAlmostEqual(r.rowe_exponent(1e-9), 4.7, delta=1e-6)
        self.assertAlmostEqual(r.rowe_exponent(1e15), 0.41 / 0.175, delta=1e-3)
        self.assertAlmostEqual(r.rowe_exponent(16.8), 3.30, delta=0.01)
        self.assertAlmostEqual(r.richardson_zaki(0.2, 16.8, "rowe"), 0.8**r.rowe_exponent(16.8))

    def test_batchelor(self):
        self.assertAlmostEqual(r.batchelor(0.1), 0.345, delta=1e-12)

    def test_sphere_terminal_velocity(self):
        # Stokes limit for a tiny sphere; the study's sphere (d = 0.35 mm) settles at Re ~ 17,
        # within 2 % of the 0.048 m/s of Rettinger & Ruede 2017.
        self.assertAlmostEqual(r.sphere_terminal_velocity(1e-6, 2500, 1000, 1e-3),
                               1500 * 9.81 * 1e-12 / 18e-3, delta=1e-9)
        self.assertAlmostEqual(r.sphere_terminal_velocity(0.35e-3, 2500, 1000, 1e-3), 0.048,
                               delta=0.001)

    def test_cube_sphericity(self):
        self.assertAlmostEqual(r.CUBE_SPHERICITY, 0.8060, delta=1e-4)
        self.assertAlmostEqual(r.cube_volume_equivalent_diameter(1.0), 1.2407, delta=1e-4)

    def test_haider_levenspiel_cubes(self):
        # The paper: Haider's formula predicts ~0.0437 m/s for the a = 0.283 mm cube.
        d_v = r.cube_volume_equivalent_diameter(0.283e-3)
        u = r.haider_levenspiel_velocity(d_v, r.CUBE_SPHERICITY, 1000.0, 2500.0, 1e-3)
        self.assertAlmostEqual(u, 0.0437, delta=0.0002)

    def test_periodic_sphere_mobility_dilute_limit(self):
        self.assertAlmostEqual(r.periodic_sphere_mobility_k(1e-4), 1.0, delta=1e-3)
        self.assertGreater(r.periodic_sphere_mobility_k(0.1), 1.3)


if __name__ == "__main__":
    unittest.main()
