"""The sweep driver's bookkeeping: finished runs are skipped, interrupted ones restart cleanly,
a changed scene runs again; the cost estimate (ctest tools_lbdem_py)."""
import os
import tempfile
import unittest
from unittest import mock

from lbdem import study

CONFIG = {"particle": {"diameter": 3.5e-4, "density": 2500},
          "fluid": {"viscosity": 1e-6, "cells_per_diameter": 6, "tau": 0.55},
          "cube_clump": "c.clump", "run": {"end": 0.01, "output_interval": 1e-3}}


class Sweep(unittest.TestCase):
    def test_skip_restart_and_rerun(self):
        with tempfile.TemporaryDirectory() as d:
            s = study.Study(dict(CONFIG, _file=os.path.join(d, "s.yaml")), "build", out=d,
                            log=lambda _: None)
            scene, cells = s.base_scene("a", [1e-3] * 3, 0.01), [10, 10, 10]
            s.finished = []
            calls = []

            def fake_run(build, path, *args, **kw):
                calls.append(path)
                return 2.0, ""
            with mock.patch.object(study.run, "run", fake_run):
                s.launch("a", scene, cells)
                self.assertEqual(len(calls), 1)
                s.launch("a", scene, cells)  # finished: skipped
                self.assertEqual(len(calls), 1)
                os.remove(os.path.join(d, "a", "result.json"))  # as if interrupted
                stale = os.path.join(d, "a", "a_bodies.csv")
                open(stale, "w").close()
                s.launch("a", scene, cells)
                self.assertEqual(len(calls), 2)
                self.assertFalse(os.path.exists(stale))  # restarted from an empty folder
                scene["time"]["end"] = 0.02  # changed scene: runs again
                s.launch("a", scene, cells)
                self.assertEqual(len(calls), 3)

    def test_estimate_fits_lattice_and_body_cost(self):
        s = study.Study(dict(CONFIG, _file="/x/s.yaml"), "build", out="/x", log=lambda _: None)
        # Defaults: 9e6 cell updates/s, 0.22 ms per body and step at 6 cells per diameter.
        self.assertAlmostEqual(s.estimate(100, 9e6, 10), 100 * (1 + 10 * 2.2e-4))
        # wall = steps (cells / 5e6 + bodies 1e-3), exactly: the fit recovers it.
        s.finished = [(n, c, b, n * (c / 5e6 + b * 1e-3)) for n, c, b in [(100, 1e5, 1),
                                                                            (200, 3e4, 27)]]
        self.assertAlmostEqual(s.estimate(300, 5e5, 64), 300 * (0.1 + 0.064), places=9)
        # One body count only: the rate is fitted with the default per-body cost, so the run
        # itself is reproduced.
        s.finished = s.finished[:1]
        self.assertAlmostEqual(s.estimate(10, 1e5, 1), 10 * (1e5 / 5e6 + 1e-3), places=9)


if __name__ == "__main__":
    unittest.main()
