#!/usr/bin/env python3
"""Stokes drag of a simple periodic array of an elongated cuboid given analytically and as an
STL mesh, with the band's hydrodynamic radius calibrated (docs/method.md, "Hydrodynamic radius
calibration"): the two must see the same parallel body, so their drags must agree.

One 4 x 4 x 16-cell cuboid, long axis z, held fixed at the centre of a triply periodic
12 x 12 x 24-cell box (dx 1e-4 m, nu 1e-6 m^2/s, tau 0.6, nearest lookup), a body force on
the fluid along x (across the long axis) and along z (along it), 3 s (steady to 0.02 %).
Prints F / U per case (F the body's load, U the superficial velocity, last fifth of the run).
Case `stl_scaled` is the earlier construction for meshes, a scale by 1 - offset S / (3 V)
about the centre, run nominal with that scale folded into the STL's.

    /usr/bin/python3 tools/mesh_vs_analytic_drag.py --build build [--axes x,z] [--out DIR]
"""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import fixed_body  # noqa: E402

DX = 1e-4
EDGES = (4, 4, 16)  # cells
BOX = (12, 12, 24)  # cells
OFFSET = 0.353  # cells: the band's excess at tau 0.6, nearest (band_calibration.cpp)


def write_box_stl(path):
    h = [e / 2 for e in EDGES]
    v = [(sx * h[0], sy * h[1], sz * h[2]) for sz in (-1, 1) for sy in (-1, 1) for sx in (-1, 1)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    with open(path, "w") as f:
        f.write("solid box\n")
        for q in quads:
            for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for i in t:
                    f.write("   vertex %g %g %g\n" % v[i])
                f.write("  endloop\n endfacet\n")
        f.write("endsolid box\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", required=True)
    ap.add_argument("--axes", default="x,z")
    ap.add_argument("--cases", default="analytic,stl,stl_scaled")
    ap.add_argument("--out", default="", help="folder for scenes and output (default: temporary)")
    args = ap.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="mesh_drag_")
    os.makedirs(out, exist_ok=True)
    stl = os.path.join(out, "box_4_4_16.stl")
    write_box_stl(stl)
    area = 2 * (EDGES[0] * EDGES[1] + EDGES[1] * EDGES[2] + EDGES[0] * EDGES[2])
    scale_old = 1 - OFFSET * area / (3 * EDGES[0] * EDGES[1] * EDGES[2])
    shapes = {
        "analytic": ("{name: s, kind: cuboid, edges: %s}" % [e * DX for e in EDGES], "calibrated"),
        "stl": ("{name: s, kind: stl, file: %s, scale: %r}" % (stl, DX), "calibrated"),
        "stl_scaled": ("{name: s, kind: stl, file: %s, scale: %r}" % (stl, DX * scale_old),
                       "nominal"),
    }
    for axis in args.axes.split(","):
        for case in args.cases.split(","):
            shape, radius = shapes[case]
            name = f"cuboid_{case}_{axis}"
            path = os.path.join(out, name + ".yaml")
            g = [0.0, 0.0, 0.0]
            g["xyz".index(axis)] = 1.0e-4
            with open(path, "w") as f:
                f.write(fixed_body.scene_text(name, [c * DX for c in BOX], DX, 0.6, radius, shape,
                                              g, 3.0, 0.05))
            force, u, change, wall = fixed_body.drag(args.build, path, axis)
            print(f"{name}: F = {force:.6g} N (change since mid-run {100 * change:+.3f} %), "
                  f"U = {u:.6g} m/s, F/U = {force / u:.6g} N s/m, wall {wall:.1f} s", flush=True)
    print(f"stl_scaled: the earlier mesh scale 1 - offset S / (3 V) = {scale_old:.5f}")


if __name__ == "__main__":
    main()
