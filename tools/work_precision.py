#!/usr/bin/python3
"""Error against run time of the validation cases: ladders of resolution (and tau), one CSV,
one plot per case, a Markdown table with the observed order and the error at 1 min / 10 min /
1 h of this machine (docs/work-precision.md).

    tools/work_precision.py --build build                          # every case, default ladders
    tools/work_precision.py --build build --cases sphere_terminal --n 4 6 --taus 0.6
    tools/work_precision.py --build build --cases sphere_terminal --n 4 6 --taus 0.6 \
        --radius nominal --require-decrease                         # the ctest version
    tools/work_precision.py --build build --radius calibrated nominal   # both radii
    tools/work_precision.py --build build --fluid                   # + Poiseuille, Couette, TG

Rungs already in <out>/work_precision.csv (same case, n, tau, radius, end, ranks) that the same
build ran (a digest of fluid_app and dem_app) are kept, not rerun, so an interrupted ladder
resumes; a rebuilt program runs its rungs again, and the tables and plots show only this
build's rungs (older ones stay in the CSV). Exit 1 when a run fails, or with
--require-decrease when the error does not fall from each rung to the next. That check is the
nominal radius's: its error is the method's leading-order discretization error, which must
fall with n; the calibrated radius cancels that term, and what is left need not fall
monotonically (docs/work-precision.md).
"""
import argparse
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from lbdem import work_precision as wp  # noqa: E402
from lbdem import scene as lbdem_scene  # noqa: E402

FLUID = ["poiseuille", "couette", "taylor_green"]


def fluid_rows(build, ns):
    """The fluid's analytic cases through the convergence study (its scenes, tau fixed)."""
    import convergence_study as cs
    from lbdem import io
    rows = []
    with tempfile.TemporaryDirectory(prefix="lbdem_wp_") as work:
        for case in FLUID:
            scene = os.path.join(cs.SCENES, case + ".yaml")
            tau = io.load_scene(scene)["fluid"]["tau"]
            for n in ns:
                r = cs.run_case(os.path.abspath(os.path.join(build, "fluid_app", "fluid_app")),
                                "", scene, n, work)
                cells = 1
                for c in r["cells"].split("x"):
                    cells *= int(c)
                rows.append({"case": case, "n": n, "tau": tau, "cells": cells,
                             "steps": r["steps"], "cell_updates": cells * r["steps"],
                             "ranks": "1", "radius": "-", "result": r["error"], "reference": 0.0,
                             "error": r["error"], "wall_s": r["time"], "box_change": 0.0,
                             "end_s": 0.0})
    return rows


def rung(r):
    return r["case"], r["n"], r["tau"], r["radius"], r["end_s"], r["ranks"]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", required=True)
    ap.add_argument("--cases", nargs="+", default=list(wp.CASES), choices=list(wp.CASES))
    ap.add_argument("--n", nargs="+", type=float, help="cells across the body (default: per case)")
    ap.add_argument("--taus", nargs="+", type=float, help="default: per case")
    ap.add_argument("--end", type=float, help="simulated end time (default: the scene's)")
    ap.add_argument("--ranks", default="1:1", help="fluid:DEM ranks")
    ap.add_argument("--radius", nargs="+", default=["calibrated"],
                    choices=["calibrated", "nominal"], help="fluid.hydrodynamic_radius")
    ap.add_argument("--fluid", action="store_true", help="add the fluid's analytic cases")
    ap.add_argument("--fluid-n", nargs="+", type=int, default=[8, 16, 32, 64])
    ap.add_argument("--out", default=os.path.join(HERE, "..", "runs", "work_precision"))
    ap.add_argument("--require-decrease", action="store_true")
    args = ap.parse_args()
    lbdem_scene.use_build(args.build)  # values of scenes come from this build

    os.makedirs(args.out, exist_ok=True)
    table = os.path.join(args.out, "work_precision.csv")
    old = wp.read_csv(table) if os.path.exists(table) else []
    ranks = tuple(int(x) for x in args.ranks.split(":"))
    build = wp.run.build_id(args.build)
    rows = []
    for case in args.cases:
        spec = wp.CASES[case]
        for radius, tau, n in ((q, t, m) for q in args.radius for t in args.taus or spec[4]
                               for m in args.n or spec[3]):
            end = args.end or wp.io.load_scene(os.path.join(wp.COUPLED, spec[0]))["time"]["end"]
            done = [r for r in old if rung(r) == (case, n, tau, radius, end, args.ranks)
                    and r["build"] == build]
            if done:
                rows.append(done[-1])
                continue
            print(f"{case}: n = {n:g}, tau = {tau:g}, {radius} radius, end = {end:g} s ...",
                  flush=True)
            try:
                r = wp.run_rung(args.build, case, n, tau, args.out, ranks, end, radius=radius)
            except RuntimeError as e:
                print(f"FAILED: {case} n = {n:g} tau = {tau:g}: {str(e)[-1500:]}")
                return 1
            print(f"  result {r['result']:.5g} (reference {r['reference']:.5g}), error "
                  f"{100 * r['error']:.2f} %, {r['cells']} cells x {r['steps']} steps, "
                  f"wall {r['wall_s']:.1f} s", flush=True)
            rows.append(r)
    if args.fluid:
        rows += [dict(r, build=build) for r in fluid_rows(args.build, args.fluid_n)]
    kept = [r for r in old if not any(rung(r) == rung(q) for q in rows)]
    wp.write_csv(table, kept + rows)
    # The tables and plots are this build's: rungs of other builds stay in the CSV only.
    summaries = wp.analyse([r for r in kept if r["build"] == build] + rows)
    md = wp.markdown(summaries)
    with open(os.path.join(args.out, "work_precision.md"), "w") as out:
        out.write(md)
    for case in sorted({c for c, _, _ in summaries}):
        wp.plot(case, summaries, os.path.join(args.out, f"{case}.png"))
    print(md)
    print(f"wrote {table}, work_precision.md and one PNG per case in {args.out}")
    ok = True
    for case in sorted({c for c, _, _ in summaries}):
        if not os.path.getsize(os.path.join(args.out, f"{case}.png")):
            print(f"FAILED: empty plot for {case}")
            ok = False
    if args.require_decrease:
        for (case, tau, radius), s in wp.analyse(rows).items():
            errs = [r["error"] for r in s["rows"]]
            # The check is the fall with resolution; the finest rung's error is reported.
            print(f"[validation] work-precision {case} tau {tau:g} {radius} radius, n = "
                  f"{s['rows'][-1]['n']:g} (reported; the check is that the error falls with "
                  f"resolution): relative error {errs[-1]:.4g}, tolerance none (run time "
                  f"{sum(r['wall_s'] for r in s['rows']):.1f} s)")
            if len(errs) < 2 or any(b >= a for a, b in zip(errs, errs[1:])):
                print(f"FAILED: {case} tau {tau:g} {radius} radius: the error does not fall "
                      "with resolution: "
                      + ", ".join(f"n={r['n']:g}: {100 * r['error']:.2f} %" for r in s["rows"]))
                ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
