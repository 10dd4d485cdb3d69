"""The cost model's pieces (scaling.py): the fit, the halo links, the geometry of the counters."""
import math
import unittest

import numpy as np

from lbdem import scaling


class Fit(unittest.TestCase):
    def test_nnls_recovers_known_costs(self):
        rng = np.random.default_rng(1)
        a = rng.uniform(1, 10, (8, 3))
        x = np.array([2e-8, 0.0, 5e-7])
        np.testing.assert_allclose(scaling.nnls(a, a @ x), x, atol=1e-15)

    def test_calibration_scales_only_the_fluid_costs_to_the_measured_busy_time(self):
        m = scaling.Model({"cell": 2e-8, "covered": 1e-7, "porosity_cell": 3e-7, "body": 2e-5,
                           "halo_byte": 2e-9, "exchange_step": 1e-4, "coupler_byte": 1e-9,
                           "dem_step": 5e-4, "atom_substep": 4e-8}, {"fluid_base": 1.0})
        ranks = [{"cells": 4.8e6, "covered_cells": 1.7e6, "bodies_in_table": 1880,
                  "halo_bytes_per_step": 3.6e6, "coupler_bytes_per_step": 3.8e5},
                 {"cells": 4.8e6, "covered_cells": 1.6e6, "bodies_in_table": 1870,
                  "halo_bytes_per_step": 3.6e6, "coupler_bytes_per_step": 3.7e5}]
        factor, c = m.calibrated(ranks, 1.5 * m.fluid_busy(ranks[0]))
        self.assertAlmostEqual(factor, 1.5)
        self.assertAlmostEqual(max(c.fluid_busy(r) for r in ranks), 1.5 * m.fluid_busy(ranks[0]))
        for k in ("exchange_step", "coupler_byte", "dem_step", "atom_substep"):
            self.assertEqual(c.costs[k], m.costs[k])
        self.assertEqual(c.memory, m.memory)
        self.assertEqual(m.costs["cell"], 2e-8)  # the original is left as it was

    def test_nnls_never_returns_a_negative_cost(self):
        a = np.array([[1.0, 1.0], [1.0, 2.0], [1.0, 3.0]])
        b = np.array([3.0, 2.0, 1.0])  # unconstrained slope -1
        x = scaling.nnls(a, b)
        self.assertTrue((x >= 0).all())
        self.assertAlmostEqual(x[1], 0.0)
        self.assertAlmostEqual(x[0], 2.0)  # b's projection on the first column

    def test_fit_costs_on_synthetic_runs(self):
        truth = {"cell": 2e-8, "porous_row": 1.5e-8, "covered": 1e-7, "porosity_cell": 3e-7,
                 "body": 2e-5, "coupler_byte": 1e-9, "atom_substep": 4e-8, "halo_byte": 2e-9,
                 "exchange_step": 1e-4, "dem_step": 5e-4}
        m = scaling.Model(truth)
        runs = []
        # Aligned cubes (rows few per covered cell) and a rotated set (many).
        for cells, rows, band, inside, bodies in (
                (195112, 130000, 40000, 24000, 64), (195112, 33000, 5000, 3000, 8),
                (195112, 60000, 12000, 12000, 8), (195112, 20000, 2500, 1000, 8),
                (195112, 58000, 5000, 3000, 8)):
            f = {"cells": cells, "porous_row_cells": rows, "covered_cells": band + inside,
                 "band_cells": band,
                 "body_interior_cells": inside, "bodies_in_table": bodies,
                 "halo_bytes_per_step": 0.0, "coupler_bytes_per_step": 200.0 * bodies}
            d = {"atoms": 27 * bodies, "ghost_atoms": 10 * bodies}
            runs.append({"f": f, "d": d, "substeps": 5,
                         "lattice": truth["cell"] * cells + truth["porous_row"] * rows
                         + truth["covered"] * (band + inside),
                         "porosity": truth["porosity_cell"] * (band + inside)
                         + truth["body"] * bodies, "exchange": m.exchange(f),
                         "dem": m.dem_busy(d, 5)})
        two = [dict(runs[1]["f"], cells=97556, porous_row_cells=16500, halo_bytes_per_step=b)
               for b in (135000, 140000)]
        fitted = scaling.fit_costs(runs, [(two, [m.fluid_busy(f) for f in two])])
        for k, v in truth.items():
            self.assertAlmostEqual(fitted.costs[k] / v, 1.0, places=6, msg=k)


    def test_porosity_costs_come_from_the_rotated_runs(self):
        runs = []
        for covered, bodies, per_cell, turned in ((64000, 64, 5e-8, False), (8000, 8, 5e-8, False),
                                                  (8500, 8, 9e-8, True), (16000, 8, 9e-8, True),
                                                  (3000, 8, 9e-8, True)):
            f = {"cells": 195112, "porous_row_cells": 40000, "covered_cells": covered,
                 "bodies_in_table": bodies, "coupler_bytes_per_step": 200.0 * bodies}
            runs.append({"f": f, "d": {"atoms": 27, "ghost_atoms": 0}, "substeps": 4,
                         "lattice": 0.004, "porosity": per_cell * covered + 1e-5 * bodies,
                         "exchange": 1e-4, "dem": 1e-4, "rotated": turned})
        fitted = scaling.fit_costs(runs)
        self.assertAlmostEqual(fitted.costs["porosity_cell"] / 9e-8, 1.0, places=6)
        self.assertAlmostEqual(fitted.costs["body"] / 1e-5, 1.0, places=6)


class Halo(unittest.TestCase):
    def test_one_rank_on_a_periodic_box_sends_nothing(self):
        self.assertEqual(scaling.halo_values((29, 29, 29), (1, 1, 1)), (0, 0))

    def test_a_slab_sends_five_values_per_face_cell_on_each_side(self):
        # Faces 5 m k - 2 m - 2 k, the 4 edges of each side add 2 m + 2 k back.
        self.assertEqual(scaling.halo_values((10, 29, 31), (3, 1, 1)), (2 * 5 * 29 * 31, 10))

    def test_a_block_with_every_neighbour_remote(self):
        n = 12
        self.assertEqual(scaling.halo_values((n, n, n), (3, 3, 3)), (30 * n * n - 12 * n, 18))


class Geometry(unittest.TestCase):
    def test_grown_volume(self):
        self.assertEqual(scaling.grown_volume((2, 3, 4), 0), 24)
        r = 1.5
        self.assertAlmostEqual(scaling.grown_volume((0, 0, 0), r), 4 / 3 * math.pi * r**3)

    def test_ghost_reach_inverts_the_grown_volume(self):
        box = (58, 58, 58)
        v = scaling.grown_volume(box, 7.25) / 58**3 - 1
        self.assertAlmostEqual(scaling.ghost_reach_from(1000, 1000 * v, box), 7.25, places=6)

    def test_porous_row_fraction_of_sparse_and_dense_suspensions(self):
        # Sparse: each body covers A L + V rows' worth of cells, A = 1.5 V^(2/3), no overlap.
        v, n, row = 1000.0, 1e-8, 100
        self.assertAlmostEqual(scaling.porous_row_fraction(n, row, v),
                               n * (150.0 * row + v), delta=1e-7)
        # The paper's phi = 0.3 suspension of 3,150 cubes (212^3 cells, about 1,000 covered
        # cells each) on blocks of 106 cells along x: every row but a few hundredths of one.
        self.assertGreater(scaling.porous_row_fraction(3150 / 212**3, 106, 1000.0), 0.99)
        self.assertEqual(scaling.porous_row_fraction(0.0, 106, 1000.0), 0.0)

    def test_dims_split_the_longest_axis_first(self):
        self.assertEqual(scaling.dims_create(2, (116, 58, 58)), (2, 1, 1))
        self.assertEqual(sorted(scaling.dims_create(64)), [4, 4, 4])

    def test_uniform_counters_of_one_rank_hold_every_body(self):
        c = scaling.uniform_counters(58, 64, 1, 1, {"covered": 1000, "band": 600, "interior": 400},
                                     10.4, 8.4, 7.0, 27)
        self.assertEqual(c["fluid"]["cells"], 58**3)
        self.assertEqual(c["fluid"]["bodies_in_table"], 64)
        self.assertAlmostEqual(c["fluid"]["covered_cells"], 64000)
        self.assertLessEqual(c["fluid"]["porous_row_cells"], 58**3)
        self.assertEqual(c["fluid"]["halo_bytes_per_step"], 0)
        self.assertAlmostEqual(c["dem"]["coupler_bytes_per_step"], 64 * 200)


if __name__ == "__main__":
    unittest.main()
