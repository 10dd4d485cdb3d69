"""lbdem.scene: the resolved scene from `fluid_app --check --json` (needs the build: ctest sets
$LBDEM_BUILD)."""
import os
import tempfile
import unittest

from lbdem import scene

SCENE = """name: tiny
time: {end: 0.01}
fluid:
  domain: [0.001, 0.001, 0.002]
  dx: 1.0e-4
  viscosity: 1e-06
  tau: 0.8
"""


class ResolvedScene(unittest.TestCase):
    def write(self, d, text):
        path = os.path.join(d, "s.yaml")
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_yaml_1_1_number_and_defaults(self):
        with tempfile.TemporaryDirectory() as d:
            r = scene.resolve(None, self.write(d, SCENE))
        s = r["scene"]
        # YAML 1.1 would give the string '1e-06'; the programs read a number.
        self.assertIsInstance(s["fluid"]["viscosity"], float)
        self.assertEqual(s["fluid"]["viscosity"], 1e-6)
        # Defaults filled in as the programs use them.
        self.assertEqual(s["log_level"], "info")
        self.assertEqual(s["fluid"]["density"], 1000)
        self.assertEqual(s["fluid"]["precision"], "double")
        # Derived numbers: dt = (tau - 1/2) dx^2 / (3 nu), cells = domain / dx.
        f = r["derived"]["fluid"]
        self.assertEqual(f["cells"], [10, 10, 20])
        self.assertAlmostEqual(f["dt"], 0.3 * 1e-8 / 3e-6, delta=1e-15)
        self.assertAlmostEqual(f["nu_lattice"], 0.1, delta=1e-15)
        self.assertEqual(r["derived"]["schedule"]["steps"], 10)
        self.assertIsNone(r["derived"]["dem"])
        self.assertEqual(r["bodies"], [])

    def test_bodies_expanded_with_mass(self):
        text = SCENE + """dem: {gravity: [0, 0, -9.81], periodic: xyz}
shapes:
- {name: ball, kind: sphere, diameter: 4.0e-4}
bodies:
- {generate: lattice, shape: ball, density: 2500, count: 2,
   region: {lo: [0, 0, 0], hi: [0.001, 0.001, 0.002]}}
"""
        with tempfile.TemporaryDirectory() as d:
            r = scene.resolve(None, self.write(d, text))
        self.assertEqual(len(r["bodies"]), 2)
        b, sh = r["bodies"][0], r["shapes"][0]
        self.assertEqual(b["shape"], "ball")
        self.assertAlmostEqual(b["mass"], 2500 * sh["volume"], delta=1e-20)
        self.assertEqual(r["scene"]["bodies"][0]["generate"], "lattice")
        self.assertGreater(r["derived"]["schedule"]["dem_substeps"], 0)

    def test_refused_scene_names_the_key(self):
        with tempfile.TemporaryDirectory() as d:
            path = self.write(d, SCENE.replace("tau: 0.8", "tau: fast"))
            with self.assertRaises(scene.SceneError) as e:
                scene.resolve(None, path)
        self.assertIn("fluid.tau", str(e.exception))


if __name__ == "__main__":
    unittest.main()
