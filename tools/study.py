#!/usr/bin/python3
"""Runs the hindered-settling study of a study file (configs/study/*.yaml; docs/study.md):
packing, single-body runs (u_T), one run per shape and solid fraction, analysis, summary.csv and
the plots settling.png, rdf.png, correlation.png, vacf.png. Resumable: run it again after an
interruption and finished runs are skipped.

    /usr/bin/python3 tools/study.py configs/study/small.yaml [--build build] [--out DIR]
        [--shapes cube] [--phi 0.1 0.3] [--precision float] [--no-render] [--plan]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import study  # noqa: E402
from lbdem import scene as lbdem_scene  # noqa: E402


def plan(s, shapes, phis):
    """Cells, steps and estimated wall time of every run (Study.estimate: perfect scaling over
    the fluid ranks assumed, so a lower bound)."""
    n = int(s.c["bodies"])
    vol = n * math.pi / 6 * s.d**3
    total = 0.0
    print(f"{'run':<22}{'cells':>16}{'steps':>9}{'bodies':>8}{'s/step':>9}{'hours':>9}")
    rows = [(f"single_{sh}", [round(k * s.d / s.dx) for k in s.c["single"]["box"]],
             float(s.c["single"]["end"]), 1) for sh in shapes]
    rows += [(f"{sh}_phi{phi:.3f}", [max(round((vol / phi) ** (1 / 3) / s.dx),
                                          math.ceil((vol / 0.4) ** (1 / 3) / s.dx - 1e-9))] * 3,
              float(s.c["run"]["end"]), n) for sh in shapes for phi in phis]
    for name, cells, end, bodies in rows:
        steps = round(end / s.dt)
        wall = s.estimate(steps, cells[0] * cells[1] * cells[2], bodies)
        total += wall
        print(f"{name:<22}{'x'.join(map(str, cells)):>16}{steps:>9}{bodies:>8}"
              f"{wall / steps:>9.3g}{wall / 3600:>9.2f}")
    per_body = s.body_cost * (s.d / s.dx / 6.0) ** 2
    print(f"total {total / 3600:.2f} h on {s.ranks} fluid rank(s) at {s.lattice_rate / 1e6:.3g} M "
          f"lattice cell updates/s per rank and {1e3 * per_body:.3g} ms per body and step "
          f"(dx = {s.dx:.4g} m, dt = {s.dt:.4g} s)")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("study")
    p.add_argument("--build", default=os.path.join(os.path.dirname(__file__), "..", "build"))
    p.add_argument("--out", help="output folder (default: the study file's 'output')")
    p.add_argument("--shapes", nargs="+", choices=["sphere", "cube"])
    p.add_argument("--phi", nargs="+", type=float, help="solid fractions (default: the file's)")
    p.add_argument("--precision", choices=study.PRECISIONS,
                   help="the fluid's number type in every run (default: the file's "
                        "fluid.precision, else the scene default, double); float is about 1.8x "
                        "faster, its error is measured in docs/precision.md. Use with --out: a "
                        "changed scene reruns the finished runs of the other precision in place")
    p.add_argument("--no-render", action="store_true", help="no body surfaces and pictures")
    p.add_argument("--plan", action="store_true",
                   help="print cells, steps and estimated hours of every run; run nothing")
    p.add_argument("--rate", type=float, default=9.0e6,
                   help="lattice cell updates per second and fluid rank, for the cost estimates "
                        "(docs/study.md)")
    p.add_argument("--body-cost", type=float, default=2.2e-4,
                   help="porosity + momentum exchange seconds per body and step at 6 cells per "
                        "diameter, for the cost estimates (docs/study.md)")
    args = p.parse_args()
    lbdem_scene.use_build(args.build)  # values of scenes come from this build
    config = study.load_study(args.study)
    if args.precision:
        config["fluid"]["precision"] = args.precision
    try:
        s = study.Study(config, args.build, args.out)
    except ValueError as e:  # a bad value in the study file
        p.error(str(e))
    shapes = args.shapes or s.c["shapes"]
    phis = args.phi or [float(v) for v in s.c["solid_fractions"]]
    s.lattice_rate, s.body_cost = args.rate, args.body_cost
    if args.plan:
        plan(s, shapes, phis)
        return 0
    render = not args.no_render and s.c.get("render", True)
    s.execute(shapes, phis, render)
    return 0


if __name__ == "__main__":
    sys.exit(main())
