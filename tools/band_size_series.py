#!/usr/bin/env python3
"""Drag of a fixed sphere or cube in a dilute periodic array over 16 poses, per size and tau.

The size series behind the band calibration's size term (docs/method.md, "Hydrodynamic radius
calibration"). Each case is PoseInvariance.Measure of build/tests/fluid_app/hlbm/
pose_invariance_tests: one body in a triply periodic box of --box-ratio times its size, Stokes
flow, 16 poses (4 unrotated sub-cell offsets, 12 random offsets and orientations), the mean K
against Sangani & Acrivos for spheres (none for cubes). For spheres it also prints the mean
hydrodynamic radius excess a_h - a and the band's own excess a_h - a + offset: the quantity the
calibration must equal.

    /usr/bin/python3 tools/band_size_series.py --build build --kinds sphere \\
        --cells 6,9,12 --taus 0.6,1.0 --csv runs/band_size_series.csv
    /usr/bin/python3 tools/band_size_series.py ... --offset 0      # the nominal band
    /usr/bin/python3 tools/band_size_series.py --fit runs/band_size_series.csv

--fit reads such a CSV (nominal or calibrated rows alike: it fits the band excess) and prints,
per tau, the least-squares a + b / R (R the radius in cells) and a + s ln(d / 8) with their
largest residuals.
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import io, references  # noqa: E402

SUMMARY = re.compile(r"K over 16 poses: mean ([0-9.]+)(?: \(reference [0-9.]+, ([-+0-9.]+) %)?"
                     r".*\(max - min\) / mean ([0-9.]+) %.*, ([0-9.]+) s")
EXCESS = re.compile(r"a_h - a over 16 poses: mean ([-+0-9.]+) cells with offset ([-+0-9.]+) "
                    r"cells: band excess ([-+0-9.]+) cells")


def radius_cells(kind, size):
    return size / 2 if kind == "sphere" else size * (3 / (4 * math.pi)) ** (1 / 3)


def measure(binary, kind, size, tau, ratio, offset, log_dir):
    box = int(round(ratio * size))
    phi = (math.pi / 6 if kind == "sphere" else 1.0) * (size / box) ** 3
    reference = references.sangani_acrivos_k(phi) if kind == "sphere" else 0.0
    case = f"{kind} drag {box} {size:g} {tau:g} {reference:.6f}"
    if offset is not None:
        case += f" {offset:g}"
    out = subprocess.run([binary, "--gtest_filter=PoseInvariance.Measure"],
                         env=dict(os.environ, POSE_CASE=case), capture_output=True, text=True)
    if log_dir:
        name = f"{kind}_d{size:g}_tau{tau:g}_box{box}_offset{offset if offset is not None else 'rule'}"
        with open(os.path.join(log_dir, name + ".log"), "w") as f:
            f.write(out.stdout)
    m = SUMMARY.search(out.stdout)
    if m is None:
        raise RuntimeError(f"{case}: no summary line\n{out.stdout[-2000:]}{out.stderr[-2000:]}")
    row = {"kind": kind, "cells": size, "tau": tau, "box": box, "phi": phi,
           "K": float(m.group(1)), "K_ref": reference,
           "error_pct": float(m.group(2)) if m.group(2) else "",
           "spread_pct": float(m.group(3)), "wall_s": float(m.group(4))}
    e = EXCESS.search(out.stdout)
    row["offset_cells"] = float(e.group(2)) if e else (offset if offset is not None else "")
    row["excess_cells"] = float(e.group(1)) if e else ""
    row["band_excess_cells"] = float(e.group(3)) if e else ""
    return row


def fit(path):
    rows = [r for r in csv.DictReader(open(path)) if r["band_excess_cells"]]
    for tau in sorted({float(r["tau"]) for r in rows}):
        pts = [(float(r["cells"]), float(r["band_excess_cells"])) for r in rows
               if float(r["tau"]) == tau]
        if len(pts) < 2:
            continue
        line = [f"tau {tau:5.3f}: " + " ".join(f"d {d:g} {e:+.4f}" for d, e in pts)]
        for name, f in (("a + b / R", lambda d: 2 / d), ("a + s ln(d/8)", lambda d: math.log(d / 8))):
            x = [f(d) for d, _ in pts]
            y = [e for _, e in pts]
            n, mx, my = len(x), sum(x) / len(x), sum(y) / len(y)
            sxx = sum((xi - mx) ** 2 for xi in x)
            b = sum((xi - mx) * (yi - my) for xi, yi in zip(x, y)) / sxx
            a = my - b * mx
            worst = max(abs(a + b * xi - yi) for xi, yi in zip(x, y))
            line.append(f"{name}: a {a:+.4f} b {b:+.4f} (largest residual {worst:.4f})")
        print(" | ".join(line))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--build", default="build")
    p.add_argument("--kinds", default="sphere")
    p.add_argument("--cells", default="6,9,12,18", help="diameter (edge) in cells")
    p.add_argument("--taus", default="0.6,0.8,1.0")
    p.add_argument("--box-ratio", type=float, default=2.0, help="box edge / body size")
    p.add_argument("--offset", type=float, default=None,
                   help="band offset in cells (default: the calibrated rule's)")
    p.add_argument("--jobs", type=int, default=1)
    p.add_argument("--log-dir", help="keep each case's output (every pose) here")
    p.add_argument("--csv", default="runs/band_size_series.csv")
    p.add_argument("--fit", metavar="CSV", help="only fit the band excess of this CSV")
    args = p.parse_args()
    if args.fit:
        fit(args.fit)
        return 0
    if args.log_dir:
        os.makedirs(args.log_dir, exist_ok=True)
    binary = os.path.join(args.build, "tests/fluid_app/hlbm/pose_invariance_tests")
    cases = [(k, float(c), float(t)) for k in args.kinds.split(",")
             for c in args.cells.split(",") for t in args.taus.split(",")]
    with ThreadPoolExecutor(args.jobs) as pool:
        futures = [pool.submit(measure, binary, k, c, t, args.box_ratio, args.offset,
                               args.log_dir)
                   for k, c, t in cases]
        rows = []
        for f in futures:
            r = f.result()
            rows.append(r)
            print(f"{r['kind']:6s} d {r['cells']:5g} tau {r['tau']:5.3f} box {r['box']:3d}: "
                  f"K {r['K']:.4f} ({r['error_pct'] if r['error_pct'] != '' else '-'} %), "
                  f"spread {r['spread_pct']:.2f} %, offset {r['offset_cells']}, "
                  f"band excess {r['band_excess_cells']}, {r['wall_s']:.0f} s", flush=True)
    io.write_rows(args.csv, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
