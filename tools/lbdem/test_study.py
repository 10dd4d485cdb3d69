"""The sweep driver's bookkeeping: finished runs are skipped, interrupted ones restart cleanly,
a changed scene or a rebuilt program runs again; the cost estimate; the momentum check (ctest
tools_lbdem_py)."""
import os
import tempfile
import unittest
from unittest import mock

import numpy as np

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
            build = ["b1"]
            with mock.patch.object(study.run, "run", fake_run), \
                    mock.patch.object(study.run, "build_id", lambda _: build[0]):
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
                s.launch("a", scene, cells)  # same scene, same build: skipped
                self.assertEqual(len(calls), 3)
                build[0] = "b2"  # rebuilt programs: runs again
                s.launch("a", scene, cells)
                self.assertEqual(len(calls), 4)

    def test_precision_reaches_every_generated_scene_only_when_chosen(self):
        def study_with(fluid):
            config = dict(CONFIG, fluid=dict(CONFIG["fluid"], **fluid), _file="/x/s.yaml",
                          single={"box": [5, 5, 24], "release_below_top": 4, "end": 0.1})
            return study.Study(config, "build", out="/x", log=lambda _: None)
        self.assertNotIn("precision", study_with({}).base_scene("a", [1e-3] * 3, 0.01)["fluid"])
        s = study_with({"precision": "float"})
        self.assertEqual(s.base_scene("a", [1e-3] * 3, 0.01)["fluid"]["precision"], "float")
        self.assertEqual(s.single_scene("sphere")[0]["fluid"]["precision"], "float")
        with self.assertRaisesRegex(ValueError, r"/x/s.yaml: fluid.precision: expected one of "
                                                r"double, float, got 'single'"):
            study_with({"precision": "single"})

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



def write_audit(path, fluid_z, bodies_z, applied_z):
    with open(path, "w") as f:
        f.write("step,time_s,fluid_px,fluid_py,fluid_pz,bodies_px,bodies_py,bodies_pz,"
                "applied_px,applied_py,applied_pz\n")
        for k, (p, b, a) in enumerate(zip(fluid_z, bodies_z, applied_z)):
            f.write(f"{k},{k * 1e-4},0,0,{p!r},0,0,{b!r},0,0,{a!r}\n")


class MomentumCheck(unittest.TestCase):
    # 10 % of a 1 mm^3 box holds bodies of 2500 kg/m^3 in water that accelerate to u_T.
    rho_p, rho_f, phi, box, u_t = 2500.0, 1000.0, 0.1, 1e-9, 0.045
    t = 1e-4 * np.arange(200)
    u_p = -u_t * (1 - np.exp(-t / 5e-3))
    bodies = rho_p * phi * box * u_p

    def check(self, fluid, applied):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "s_momentum.csv")
            write_audit(path, fluid, self.bodies, applied)
            change = study.momentum_change(path)
        return change, study.momentum_warning("s", {"momentum_change": change})

    def test_a_box_that_holds_its_momentum_with_rho_p_not_rho_f_does_not_warn(self):
        fluid = -self.bodies  # the fluid outside the bodies carries the opposite momentum
        # Its volume flux j = phi u_p + (fluid momentum) / (rho_f V) = phi u_p (1 - rho_p / rho_f)
        # is 0.15 u_T at the end, which the former volume-flux test (> 0.1 u_T) called a loss.
        j = self.phi * self.u_p + fluid / (self.rho_f * self.box)
        self.assertAlmostEqual(j[-1] / self.u_t, 0.15 * (1 - np.exp(-199e-4 / 5e-3)), places=12)
        change, warning = self.check(fluid, np.zeros_like(fluid))
        self.assertLess(change, 1e-12)
        self.assertIsNone(warning)

    def test_an_applied_impulse_is_accounted_for(self):
        applied = 1e-3 * self.bodies[-1] * np.arange(len(self.t))  # e.g. a controller's force
        change, warning = self.check(-self.bodies + applied, applied)
        self.assertLess(change, 1e-12)
        self.assertIsNone(warning)

    def test_a_lost_force_warns(self):
        # The fluid keeps its momentum while the bodies gain theirs: no reaction reached it.
        change, warning = self.check(np.zeros_like(self.bodies), np.zeros_like(self.bodies))
        # From step 1 on (the audit's first coupled step).
        self.assertAlmostEqual(change, 1 - self.bodies[1] / self.bodies[-1], places=12)
        self.assertIn("WARNING the momentum of fluid + bodies changed by 0.98", warning)
        self.assertNotIn("None", warning)


if __name__ == "__main__":
    unittest.main()
