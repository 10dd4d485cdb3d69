#!/usr/bin/env python3
"""Stokes drag of a simple periodic array of a torus given as an STL mesh (non-convex: the
band's calibration must widen its hole), against a resolution series (docs/method.md,
"Hydrodynamic radius calibration").

Torus ring 0.5 mm, tube 0.2 mm (48 x 24 segments, axis z) fixed at the centre of a triply
periodic 2 x 2 x 1 mm box, body force on the fluid along x, 1.5 s (steady to 0.2 %). Cases
KIND_dN_tTT: KIND nom (nominal radius), cal (calibrated), old (the earlier mesh construction:
nominal with the STL scaled by 1 - offset S / (3 V)); dN the spacing dx = 1e-4 m / N (N = 1, 2,
3, 4: tube 4 to 16 cells across); tTT tau 0.6 or 1.0. Prints F / U (load over superficial
velocity, last fifth of the run).

    /usr/bin/python3 tools/torus_drag_convergence.py --build build \
        --cases cal_d1_t06,old_d1_t06,nom_d2_t10,nom_d3_t10 [--out DIR]
"""
import argparse
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import fixed_body  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("--build", required=True)
ap.add_argument("--cases", required=True)
ap.add_argument("--out", default="", help="folder for scenes and output (default: temporary)")
args = ap.parse_args()
BUILD = args.build
CASES = args.cases.split(",")
HERE = args.out or tempfile.mkdtemp(prefix="torus_drag_")
os.makedirs(HERE, exist_ok=True)
RING, TUBE, NU, NV = 0.5e-3, 0.2e-3, 48, 24
BOX = (2.0e-3, 2.0e-3, 1.0e-3)

def torus_stl(path):
    P = lambda i, j: ((RING + TUBE * math.cos(2 * math.pi * (j % NV) / NV)) * math.cos(2 * math.pi * (i % NU) / NU),
                      (RING + TUBE * math.cos(2 * math.pi * (j % NV) / NV)) * math.sin(2 * math.pi * (i % NU) / NU),
                      TUBE * math.sin(2 * math.pi * (j % NV) / NV))
    with open(path, "w") as f:
        f.write("solid t\n")
        for i in range(NU):
            for j in range(NV):
                for t in ((P(i, j), P(i + 1, j), P(i + 1, j + 1)), (P(i, j), P(i + 1, j + 1), P(i, j + 1))):
                    f.write(" facet normal 0 0 0\n  outer loop\n")
                    for v in t:
                        f.write("   vertex %.12g %.12g %.12g\n" % v)
                    f.write("  endloop\n endfacet\n")
        f.write("endsolid t\n")

stl = os.path.join(HERE, "torus.stl")
torus_stl(stl)
# The earlier construction: scale 1 - offset S / (3 V), S = 4 pi^2 R r, V = 2 pi^2 R r^2.
def scale_old(offset):
    return 1 - offset * 2 / (3 * TUBE)

# case: name -> (dx, tau, radius, scale); the band's excess in cells (band_calibration.cpp).
EXC = {0.6: 0.353, 1.0: -0.129}
defs = {}
for dx, tag in ((1e-4, "d1"), (5e-5, "d2"), (1e-4 / 3, "d3"), (2.5e-5, "d4")):
    for tau in (0.6, 1.0):
        t = f"t{int(tau * 10):02d}"
        defs[f"nom_{tag}_{t}"] = (dx, tau, "nominal", 1.0)
        defs[f"cal_{tag}_{t}"] = (dx, tau, "calibrated", 1.0)
        defs[f"old_{tag}_{t}"] = (dx, tau, "nominal", scale_old(EXC[tau] * dx))
for case in CASES:
    dx, tau, radius, scale = defs[case]
    path = os.path.join(HERE, case + ".yaml")
    with open(path, "w") as f:
        shape = "{name: s, kind: stl, file: %s, scale: %r}" % (stl, scale)
        f.write(fixed_body.scene_text(case, BOX, dx, tau, radius, shape, [1.0e-4, 0, 0], 1.5, 0.02))
    fd, u, change, wall = fixed_body.drag(BUILD, path, "x", timeout=400)
    print(f"{case}: dx {dx:g} tau {tau} {radius} scale {scale:.5f}: F/U = {fd / u:.6g} N s/m "
          f"(F change since mid-run {100 * change:+.3f} %), wall {wall:.1f} s", flush=True)
