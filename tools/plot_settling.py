#!/usr/bin/python3
"""Plots the settling of a coupled run: the mean body velocity in the zero-volume-flux frame
against time, normalised by the single-body terminal velocity u_T of this code, with the
Richardson-Zaki expectation (n from Re, default the study's 16.8) for the run's solid fraction.

    /usr/bin/python3 tools/plot_settling.py SCENE --terminal-scene SINGLE_BODY_SCENE
    /usr/bin/python3 tools/plot_settling.py SCENE --u-terminal 0.0457

The settling velocity is <u_p,z> - j with j the volume flux, which is the fluid series' mean_uz
(it averages over all nodes, bodies included; docs/study.md, "Zero-volume-flux frame"). u_T is
the mean settling speed over the last 20 % of a single-body run at the same resolution and tau
(--terminal-scene), or given (--u-terminal); without either the paper's 0.0457 m/s is used and
the plot says so. Reads <dem dir>/<name>_bodies.csv and <fluid dir>/<name>_series.csv; writes
<dem dir>/<name>_settling.png and prints the steady-state mean with its block-averaged error.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import analysis, io, references  # noqa: E402

PAPER_CUBE_U_T = 0.0457  # m/s, the paper's single cube (a = 0.283 mm)


def shape_volume(shape):
    kind = shape["kind"]
    if kind == "sphere":
        return math.pi / 6 * shape["diameter"] ** 3
    if kind == "cube":
        return shape["edge"] ** 3
    if kind == "cuboid":
        return float(np.prod(shape["edges"]))
    if kind == "ellipsoid":
        return 4 / 3 * math.pi * float(np.prod(shape["semi_axes"]))
    raise ValueError(f"plot_settling: shape kind {kind} has no volume formula here")


def terminal_velocity(scene_path):
    """Mean settling speed of body 0 over the last 20 % of a single-body run, and its change
    across that window (relative)."""
    tr = io.Trace(io.trace_path(scene_path))
    speed = -tr["vz"][:, 0]
    tail = speed[tr.time >= 0.8 * tr.time[-1]]
    return float(tail.mean()), float((tail[-1] - tail[0]) / tail.mean())


def settling(scene_path, u_t, reynolds):
    """Everything the plot shows, as a dict."""
    s = io.load_scene(scene_path)
    tr = io.Trace(io.trace_path(scene_path, s))
    series_file = io.series_path(scene_path, s)
    if not os.path.exists(series_file):
        raise SystemExit(f"plot_settling: {series_file} is missing: the zero-volume-flux frame "
                         "needs the fluid series (fluid.output.series in the scene)")
    series = io.read_series(series_file)
    box = s["fluid"]["domain"]
    if len(s["shapes"]) != 1:
        raise SystemExit("plot_settling: one shape per scene (the solid fraction needs its volume)")
    phi = len(tr.id) * shape_volume(s["shapes"][0]) / (box[0] * box[1] * box[2])
    j = np.interp(tr.time, series["time_s"], series["mean_uz_m_s"])
    speed = -analysis.settling_velocity(tr["vz"].mean(axis=1), j)
    start = analysis.mser_start(speed)
    mean, err = analysis.block_average(speed[start:])
    return {"name": s["name"], "bodies": len(tr.id), "phi": phi, "time": tr.time, "speed": speed,
            "t_steady": tr.time[start], "mean": mean, "error": err, "u_t": u_t,
            "expected": u_t * references.richardson_zaki(phi, reynolds),
            "n": references.richardson_zaki_exponent(reynolds),
            "png": os.path.join(io.dem_output_dir(scene_path, s), s["name"] + "_settling.png")}


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("scene")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--terminal-scene", help="scene of a single-body run (already run) at the "
                                            "same resolution and tau")
    g.add_argument("--u-terminal", type=float, help="single-body terminal velocity in m/s")
    p.add_argument("--reynolds", type=float, default=16.8,
                   help="single-body Re for the Richardson-Zaki exponent (the study: 16.8)")
    args = p.parse_args(argv)
    source = "given"
    if args.terminal_scene:
        u_t, drift = terminal_velocity(args.terminal_scene)
        source = f"single-body run, change {100 * drift:+.2f} % over its last 20 %"
    elif args.u_terminal:
        u_t = args.u_terminal
    else:
        u_t, source = PAPER_CUBE_U_T, "the paper's cube, NOT this code's: pass --terminal-scene"
    r = settling(args.scene, u_t, args.reynolds)
    print(f"{r['name']}: {r['bodies']} bodies, solid fraction {r['phi']:.4f}; settling velocity in "
          f"the zero-volume-flux frame {r['mean']:.5g} +- {r['error']:.2g} m/s (steady from "
          f"t = {r['t_steady']:.3g} s); u/u_T = {r['mean'] / u_t:.4f} +- {r['error'] / u_t:.4f} "
          f"with u_T = {u_t:.5g} m/s ({source}); Richardson-Zaki (n = {r['n']:.2f}) expects "
          f"{r['expected'] / u_t:.4f}")
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(r["time"], r["speed"] / u_t, label="bodies, zero-volume-flux frame")
    ax.axvline(r["t_steady"], color="gray", lw=0.8, ls=":", label="steady state from")
    ax.axhline(r["expected"] / u_t, color="k", ls="--",
               label=f"Richardson-Zaki, phi = {r['phi']:.3f}, n = {r['n']:.2f}")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(f"u / u_T  (u_T = {u_t:.4g} m/s, {source.split(',')[0]})", fontsize=8)
    ax.set_title(f"{r['name']}: {r['bodies']} bodies; steady {r['mean'] / u_t:.3f} "
                 f"+- {r['error'] / u_t:.3f}", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(r["png"], dpi=120)
    print(f"plot: {r['png']}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
