"""tools/plot_settling.py on a synthetic run with a known answer (ctest tools_lbdem_py)."""
import contextlib
import io as _io
import os
import sys
import tempfile
import unittest

import numpy as np
import yaml

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import plot_settling  # noqa: E402

HEADER = "time,id,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz,fx,fy,fz,tx,ty,tz\n"


def write_run(folder, name, n, box, vz_of_t, shape, series=None):
    # A valid scene: the tools read it through fluid_app --check --json (lbdem/scene.py).
    scene = {"name": name, "time": {"end": 0.1},
             "fluid": {"domain": [box] * 3, "dx": box / 10, "viscosity": 1e-6,
                       "output": {"directory": ".", "series": {"interval": 1e-3}}},
             "dem": {"output": {"directory": "."}}, "shapes": [shape]}
    with open(os.path.join(folder, name + ".yaml"), "w") as f:
        yaml.safe_dump(scene, f)
    times = np.arange(0, 0.1, 1e-3)
    with open(os.path.join(folder, name + "_bodies.csv"), "w") as f:
        f.write(HEADER)
        for t in times:
            for k in range(n):
                f.write(f"{t},{k},{k * 1e-4},0,0,0,0,{vz_of_t(t, k)},0,0,0,1,0,0,0,0,0,0,0,0,0\n")
    if series:
        with open(os.path.join(folder, name + "_series.csv"), "w") as f:
            f.write("step,time_s,mean_ux_m_s,mean_uy_m_s,mean_uz_m_s\n")
            for k, t in enumerate(times):
                f.write(f"{k},{t},0,0,{series(t)}\n")
    return os.path.join(folder, name + ".yaml")


class PlotSettling(unittest.TestCase):
    def test_zero_volume_flux_frame_and_u_t_from_a_run(self):
        # 10 cubes of edge 1e-4 in a box of edge 10^(1/3)/0.3^(1/3) * 1e-4: phi = 0.3. Bodies
        # settle at -0.02 m/s (+- 0.002 between bodies) after a transient; the fluid rises at
        # +0.003 m/s, so the series (all nodes) reports j = 0.3 (-0.02) + 0.7 (0.003) = -0.0039 and
        # the settling velocity in the zero-volume-flux frame is 0.0161 m/s. The single body
        # settles at 0.05 m/s: u/u_T = 0.322.
        edge, n, phi = 1e-4, 10, 0.3
        box = (n * edge**3 / phi) ** (1 / 3)
        up = lambda t: -0.02 * (1 - np.exp(-t / 0.005))  # noqa: E731
        uf = lambda t: 0.003 * (1 - np.exp(-t / 0.005))  # noqa: E731
        with tempfile.TemporaryDirectory() as d:
            scene = write_run(d, "many", n, box, lambda t, k: up(t) + 0.002 * (k - 4.5) / 4.5,
                              {"kind": "cube", "name": "c", "edge": edge},
                              series=lambda t: phi * up(t) + (1 - phi) * uf(t))
            single = write_run(d, "one", 1, 1e-3, lambda t, k: -0.05 * (1 - np.exp(-t / 0.005)),
                               {"kind": "cube", "name": "c", "edge": edge})
            out = _io.StringIO()
            with contextlib.redirect_stdout(out):
                plot_settling.main([scene, "--terminal-scene", single])
            r = plot_settling.settling(scene, 0.05, 16.8)
            self.assertAlmostEqual(r["phi"], 0.3, places=12)
            self.assertAlmostEqual(r["mean"], 0.0161, delta=1e-6)
            self.assertGreater(r["t_steady"], 0.01)  # the transient is left out
            self.assertIn("u/u_T = 0.3220", out.getvalue())
            self.assertTrue(os.path.exists(os.path.join(d, "many_settling.png")))


if __name__ == "__main__":
    unittest.main()
