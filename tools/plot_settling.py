#!/usr/bin/env python3
"""Plots the settling of a coupled run: mean body velocity against time, in the frame of zero
volume flux, with the Richardson-Zaki expectation for the scene's solid fraction.

    /usr/bin/python3 tools/plot_settling.py configs/demo/settling_cubes.yaml [--u-terminal 0.0457]

Reads the DEM body trace (<dem.output.directory>/<name>_bodies.csv) and, if the scene writes
it, the fluid series (<fluid.output.directory>/<name>_series.csv); writes
<dem.output.directory>/<name>_settling.png and prints the late-time mean.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import yaml  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "analysis"))
import references  # noqa: E402


def resolve(scene, path):
    return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(scene)), path))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("scene")
    p.add_argument("--u-terminal", type=float, default=0.0457,
                   help="single-body terminal velocity in m/s (default: the paper's cube)")
    p.add_argument("--reynolds", type=float, default=12.9, help="Re for the R-Z exponent")
    args = p.parse_args()
    with open(args.scene) as f:
        s = yaml.safe_load(f)
    name = s["name"]
    dem_dir = resolve(args.scene, s["dem"].get("output", {}).get("directory", "."))
    rows = list(csv.DictReader(open(os.path.join(dem_dir, name + "_bodies.csv"))))
    by_time = {}
    for r in rows:
        by_time.setdefault(float(r["time"]), []).append(float(r["vz"]))
    times = sorted(by_time)
    up = [sum(by_time[t]) / len(by_time[t]) for t in times]

    # Solid fraction from the bodies: volume of one cube or sphere times the count.
    box = s["fluid"]["domain"]
    vbox = box[0] * box[1] * box[2]
    shape = s["shapes"][0]
    v1 = shape["edge"] ** 3 if shape["kind"] == "cube" else math.pi / 6 * shape["diameter"] ** 3
    nb = len(by_time[times[0]])
    phi = nb * v1 / vbox

    # Zero-volume-flux frame: j = phi <u_p> + (1 - phi) <u_f> (fluid mean from the series).
    uf = {}
    out = s["fluid"].get("output", {})
    series = os.path.join(resolve(args.scene, out.get("directory", ".")), name + "_series.csv")
    if os.path.exists(series):
        for r in csv.DictReader(open(series)):
            key = [k for k in r if k.strip().startswith("mean_uz") or k.strip() == "uz"]
            if key:
                uf[float(r["time_s"])] = float(r[key[0]])
    def fluid_at(t):
        if not uf:
            return 0.0
        tt = min(uf, key=lambda x: abs(x - t))
        return uf[tt]
    us = [-(u - (phi * u + (1 - phi) * fluid_at(t))) for t, u in zip(times, up)]

    expected = args.u_terminal * references.richardson_zaki(phi, args.reynolds)
    late = [u for t, u in zip(times, us) if t >= 0.75 * times[-1]]
    mean_late = sum(late) / len(late)
    print(f"{name}: {nb} bodies, solid fraction {phi:.3f}; mean settling velocity over the last "
          f"quarter {mean_late:.4g} m/s; Richardson-Zaki (n = "
          f"{references.richardson_zaki_exponent(args.reynolds):.2f}) expects {expected:.4g} m/s "
          f"(u_T = {args.u_terminal} m/s)")

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(times, us, label="mean settling velocity (zero volume flux frame)")
    ax.axhline(expected, color="k", ls="--", label=f"Richardson-Zaki, phi = {phi:.2f}")
    ax.axhline(args.u_terminal, color="gray", ls=":", label="single body u_T")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("settling velocity (m/s)")
    ax.set_title(f"{name}: {nb} bodies")
    ax.legend(fontsize=8)
    fig.tight_layout()
    png = os.path.join(dem_dir, name + "_settling.png")
    fig.savefig(png, dpi=120)
    print(f"plot: {png}")


if __name__ == "__main__":
    main()
