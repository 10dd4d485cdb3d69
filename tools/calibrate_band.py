#!/usr/bin/env python3
"""Measures the hydrodynamic radius of a sphere's HLBM band, per relaxation time (Ladd 1994).

The drag on a fixed sphere in a dilute simple cubic array (box L = 3 d, phi 0.019, Re 0.01)
is compared with Sangani & Acrivos: the radius a_h at which K_SA(phi(a_h)) a_h / a equals the
measured K = F / (6 pi mu a U) is the radius the flow sees. The excess (a_h - a) / dx, in
cells, is what fluid.hydrodynamic_radius: calibrated removes (docs/validation.md section 5,
the table in coupler_lib/scene/band_calibration.cpp). Each case runs through the real entry point
(mpirun fluid_app : dem_app), twice: sphere centred on a node and off it by a generic fraction
of a cell, because the nearest-voxel band depends on where the surface cuts the cells.

    /usr/bin/python3 tools/calibrate_band.py --build build --taus 0.55,0.6,0.8 --cells 8
    /usr/bin/python3 tools/calibrate_band.py --build build --taus 0.6 --radius calibrated

With --radius calibrated the same runs check the calibration: the excess left should be
near zero at every tau (--max-excess makes that a check: exit 1 if any |a_h - a| is larger,
in cells). Prints one row per case (K, a_h - a, wall time) and writes a CSV.
"""
import argparse
import math
import os
import sys
import tempfile

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import io, references, run  # noqa: E402

VISCOSITY = 1.0e-6  # m^2/s
DENSITY = 1000.0
DX = 1.0e-4
BOX_DIAMETERS = 3  # L / d
REYNOLDS = 0.01
# Slowest transient of the box decays as exp(-4 pi^2 nu t / L^2): 0.35 L^2 / nu leaves 1e-6.
END_TIME_L2_OVER_NU = 0.35
WINDOW = 0.1  # averaging window, fraction of the run
OFFSETS = {"node": (0.0, 0.0, 0.0), "off": (0.31, 0.17, 0.43)}  # cells


def scene_for(tau, cells, offset, radius, lookup, out_dir):
    d = cells * DX
    box = BOX_DIAMETERS * d
    a = d / 2
    u = REYNOLDS * VISCOSITY / d
    phi = 4.0 / 3.0 * math.pi * a**3 / box**3
    # Body force so that the superficial velocity is about u at the Sangani-Acrivos drag.
    g = references.sangani_acrivos_k(phi) * 6 * math.pi * DENSITY * VISCOSITY * a * u / (
        DENSITY * box**3)
    centre = [box / 2 + o * DX for o in offset]
    name = f"band_{cells}_{tau:g}_{radius}_{lookup}".replace(".", "p")
    return name, {
        "name": name,
        "time": {"end": END_TIME_L2_OVER_NU * box**2 / VISCOSITY, "progress_interval": 1000},
        "fluid": {
            "domain": [box] * 3, "dx": DX, "viscosity": VISCOSITY, "density": DENSITY,
            "tau": tau, "characteristic_velocity": u, "characteristic_length": d,
            "body_force": [0, 0, g], "porosity_lookup": lookup, "hydrodynamic_radius": radius,
            "boundaries": {k: "periodic" for k in
                           ("x_min", "x_max", "y_min", "y_max", "z_min", "z_max")},
            "output": {"directory": out_dir,
                       "series": {"interval": WINDOW * END_TIME_L2_OVER_NU * box**2 /
                                  VISCOSITY / 20}},
        },
        "dem": {"gravity": [0, 0, 0], "periodic": "xyz", "output": {"directory": out_dir}},
        "shapes": [{"name": "sphere", "kind": "sphere", "diameter": d}],
        "bodies": [{"shape": "sphere", "position": centre, "density": 1.0e12}],
        "coupling": {"output_interval": WINDOW * END_TIME_L2_OVER_NU * box**2 / VISCOSITY / 20},
    }


def hydrodynamic_radius(k_measured, a, box):
    """a_h with K_SA(phi(a_h)) a_h / a = k_measured (bisection; the left side grows with a_h)."""
    def excess(ah):
        return references.sangani_acrivos_k(4.0 / 3.0 * math.pi * ah**3 / box**3) * ah / a \
            - k_measured
    lo, hi = 0.5 * a, 1.5 * a
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if excess(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def measure(build, tau, cells, offset, radius, lookup, work):
    name, scene = scene_for(tau, cells, OFFSETS[offset], radius, lookup, work)
    path = os.path.join(work, name + "_" + offset + ".yaml")
    scene["name"] = name + "_" + offset
    with open(path, "w") as f:
        yaml.safe_dump(scene, f, sort_keys=False)
    wall, _ = run.run(build, path)
    series = io.read_rows(io.series_path(path, {"name": scene["name"], "fluid": scene["fluid"]}))
    bodies = io.read_trace_by_body(io.trace_path(path, {"name": scene["name"], "dem": scene["dem"]}))
    t_end = series[-1]["time_s"]
    u = sum(r["mean_uz_m_s"] for r in series if r["time_s"] >= (1 - WINDOW) * t_end)
    u /= sum(1 for r in series if r["time_s"] >= (1 - WINDOW) * t_end)
    rows = bodies[0]
    tail = [r["fz"] for r in rows if r["time"] >= (1 - WINDOW) * t_end]
    force = sum(tail) / len(tail)
    a = cells * DX / 2
    box = BOX_DIAMETERS * cells * DX
    k = force / (6 * math.pi * DENSITY * VISCOSITY * a * u)
    ah = hydrodynamic_radius(k, a, box)
    return {"tau": tau, "cells": cells, "offset": offset, "radius": radius, "lookup": lookup,
            "K": k, "K_SA": references.sangani_acrivos_k(4 / 3 * math.pi * a**3 / box**3),
            "excess_cells": (ah - a) / DX, "Re": 2 * a * u / VISCOSITY, "wall_s": wall}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default="build")
    p.add_argument("--taus", default="0.52,0.55,0.6,0.7,0.8,1.0,1.5")
    p.add_argument("--cells", default="8", help="sphere diameters in cells, comma-separated")
    p.add_argument("--offsets", default="node,off")
    p.add_argument("--radius", default="nominal", choices=("nominal", "calibrated"))
    p.add_argument("--lookup", default="nearest", choices=("nearest", "trilinear"))
    p.add_argument("--csv", default="runs/band_calibration.csv")
    p.add_argument("--max-excess", type=float, default=None,
                   help="fail when any |a_h - a| exceeds this many cells")
    args = p.parse_args()
    rows = []
    with tempfile.TemporaryDirectory(prefix="band_") as work:
        for cells in (int(c) for c in args.cells.split(",")):
            for tau in (float(t) for t in args.taus.split(",")):
                for offset in args.offsets.split(","):
                    r = measure(args.build, tau, cells, offset, args.radius, args.lookup, work)
                    rows.append(r)
                    print(f"d/dx {cells:3d} tau {tau:5.3f} {offset:4s} {args.radius}: "
                          f"K {r['K']:.4f} (S&A {r['K_SA']:.4f}, {100 * (r['K'] / r['K_SA'] - 1):+.2f} %)"
                          f"  a_h - a = {r['excess_cells']:+.3f} cells  Re {r['Re']:.3g}  "
                          f"{r['wall_s']:.0f} s", flush=True)
    io.write_rows(args.csv, rows)
    if args.max_excess is not None:
        worst = max(abs(r["excess_cells"]) for r in rows)
        wall = sum(r["wall_s"] for r in rows)
        print(f"[validation] band calibration d/dx {args.cells} tau {args.taus} (re-runs the "
              f"calibration's own configuration): |a_h - a| in cells error {worst:.4g}, "
              f"tolerance {args.max_excess:g} (run time {wall:.1f} s)")
        if worst > args.max_excess:
            print(f"FAILED: largest |a_h - a| {worst:.3f} cells above {args.max_excess:g}")
            return 1
        print(f"largest |a_h - a| {worst:.3f} cells (bound {args.max_excess:g})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
