"""work_precision's analysis on synthetic ladders with known order and cost law."""
import math
import os
import tempfile
import unittest

import yaml

from lbdem import scene as lbdem_scene
from lbdem import work_precision as wp


def ladder(order, cost_power, taus=(0.6,), radius="calibrated"):
    rows = []
    for tau in taus:
        for n in (4, 6, 9, 13.5):
            rows.append({"case": "synthetic", "n": n, "tau": tau, "cells": int(n ** 3),
                         "steps": int(n * n), "cell_updates": int(n ** 5), "ranks": "1:1",
                         "result": 1 + 0.5 * n ** -order, "reference": 1.0,
                         "error": 0.5 * n ** -order, "wall_s": 0.01 * n ** cost_power,
                         "box_change": 0.0, "end_s": 0.1, "radius": radius,
                         "build": "0123456789ab"})
    return rows


class WorkPrecision(unittest.TestCase):
    def test_order_and_cost_law_recovered(self):
        s = wp.analyse(ladder(2.0, 5.0))[("synthetic", 0.6, "calibrated")]
        self.assertAlmostEqual(s["order"], 2.0, places=9)
        self.assertAlmostEqual(s["cost_power"], 5.0, places=9)
        for r in s["rows"][1:]:
            self.assertAlmostEqual(r["order"], 2.0, places=9)
        nx = s["next"]
        self.assertAlmostEqual(nx["n"], 13.5 * 1.5)
        self.assertAlmostEqual(nx["wall_s"], 0.01 * nx["n"] ** 5, delta=1e-6 * nx["wall_s"])
        self.assertAlmostEqual(nx["error"], 0.5 * nx["n"] ** -2, delta=1e-9)

    def test_error_at_budget(self):
        s = wp.analyse(ladder(2.0, 5.0))[("synthetic", 0.6, "calibrated")]
        # error = 0.5 (wall / 0.01)^(-2/5) on and beyond the ladder.
        for label, budget in wp.BUDGETS:
            e, how = s["budget"][label]
            self.assertAlmostEqual(e, 0.5 * (budget / 0.01) ** -0.4, delta=1e-9)
        self.assertEqual(wp.error_at(s["rows"], 1e-6, -2, 0, 5, 0)[1], "below the first rung")

    def test_no_law_from_an_order_above_the_scheme(self):
        # An error falling as n^-4 is a calibrated radius passing through zero, not convergence.
        s = wp.analyse(ladder(4.0, 3.0))[("synthetic", 0.6, "calibrated")]  # rungs end at 25 s
        self.assertIsNone(s["next"]["error"])
        e, how = s["budget"]["1 h"]
        self.assertIsNone(e)
        self.assertIn("above 2.5", how)
        self.assertIn("not extrapolated", wp.markdown({("synthetic", 0.6, "calibrated"): s}))

    def test_csv_round_trip_and_outputs(self):
        rows = ladder(1.0, 4.0, taus=(0.6, 0.8))
        summaries = wp.analyse(rows)
        self.assertEqual(len(summaries), 2)
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "wp.csv")
            wp.write_csv(path, rows)
            back = wp.read_csv(path)
            self.assertEqual(len(back), len(rows))
            self.assertTrue(all(math.isclose(a["error"], b["error"]) for a, b in zip(rows, back)))
            self.assertEqual({(r["radius"], r["build"]) for r in back},
                             {("calibrated", "0123456789ab")})
            wp.plot("synthetic", summaries, os.path.join(d, "synthetic.png"))
            self.assertGreater(os.path.getsize(os.path.join(d, "synthetic.png")), 1000)
        md = wp.markdown(summaries)
        self.assertIn("error at 1 h", md)
        self.assertEqual(md.count("| synthetic | 0.8 |"), 5)

    def test_each_radius_is_its_own_ladder(self):
        rows = ladder(1.0, 4.0) + ladder(2.0, 4.0, radius="nominal")
        summaries = wp.analyse(rows)
        self.assertAlmostEqual(summaries[("synthetic", 0.6, "calibrated")]["order"], 1.0)
        self.assertAlmostEqual(summaries[("synthetic", 0.6, "nominal")]["order"], 2.0)

    def test_build_id_follows_the_binaries(self):
        with tempfile.TemporaryDirectory() as d:
            for exe in ("fluid_app", "dem_app"):
                os.makedirs(os.path.join(d, exe))
                with open(os.path.join(d, exe, exe), "wb") as f:
                    f.write(b"program " + exe.encode())
            first = wp.run.build_id(d)
            self.assertEqual(first, wp.run.build_id(d))
            with open(os.path.join(d, "dem_app", "dem_app"), "ab") as f:
                f.write(b" rebuilt")
            self.assertNotEqual(first, wp.run.build_id(d))

    def test_rung_scene_keeps_body_and_box(self):
        base = os.path.join(wp.COUPLED, "sphere_terminal_d6_tau06.yaml")
        scene, change = wp.rung_scene(base, 4, 0.7, "out")
        self.assertAlmostEqual(scene["fluid"]["dx"], 3.5e-4 / 4)
        self.assertAlmostEqual(change, 0.0, places=12)
        self.assertEqual(scene["fluid"]["tau"], 0.7)
        self.assertEqual(scene["dem"]["output"]["directory"], "out")
        self.assertEqual(scene["fluid"]["hydrodynamic_radius"], "calibrated")
        nominal, _ = wp.rung_scene(base, 4, 0.7, "out", radius="nominal")
        self.assertEqual(nominal["fluid"]["hydrodynamic_radius"], "nominal")
        self.assertNotEqual(nominal["name"], scene["name"])
        # The programs read a written rung as meant (lbdem/scene.py); the rung above is refused
        # (Mach 0.49), this one is a rung of the default ladder.
        scene, _ = wp.rung_scene(base, 6, 0.6, "out")
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "rung.yaml")
            with open(path, "w") as f:
                yaml.safe_dump(scene, f, sort_keys=False)
            derived = lbdem_scene.resolve(None, path)["derived"]
        self.assertEqual(derived["fluid"]["cells"], [30, 30, 144])
        self.assertAlmostEqual(derived["fluid"]["dt"], 0.1 * (3.5e-4 / 6) ** 2 / 3e-6,
                               delta=1e-15)


if __name__ == "__main__":
    unittest.main()
