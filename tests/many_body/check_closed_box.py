#!/usr/bin/env python3
"""Many spheres settling with contacts in a closed box (closed_box_spheres.yaml): runs the
coupled scene and checks, from the body trace (one row per body and output time):

  * no overlap beyond a bound: sphere-sphere (d - |x_i - x_j|) and sphere-wall (r - distance
    to the wall), at every output time;
  * every body stays in the box (centre at least r - overlap bound from each wall);
  * the mean settling speed of all bodies over the window, before the first reaches the floor,
    lies in a stated band of the single-sphere Stokes speed (rho_p - rho_f) g d^2 / (18 mu);
  * with --rest: at the end the bodies have settled (mean speed below a bound; a few may still
    roll off the second layer into a gap) and every body rests on the floor or on another body
    (gap below the contact bound).

    check_closed_box.py --build build --scene closed_box_spheres.yaml --ranks 1:1 [--rest]
Prints every measured number, the bound it is checked against and the wall time; exit 1 if a
check fails.
"""
import argparse
import itertools
import os
import sys

import numpy as np

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")
sys.path.insert(0, TOOLS)
from lbdem import io, run  # noqa: E402

# Bounds (docs/testing.md gives the measured values they were sized from).
MAX_OVERLAP = 0.02       # of d (measured 0.0070 sphere-sphere, 0.0089 sphere-wall)
# Mean settling speed / Stokes speed over the window (measured 0.613, docs/validation-table.md).
SPEED_BAND = (0.35, 0.85)
WINDOW = (0.05, 0.20)    # s: after the ~5 ms relaxation, before the lowest body lands
REST_SPEED = 0.06        # of the Stokes speed, mean speed of the bodies at the end (--rest)
CONTACT_GAP = 0.03       # of d: a body this close to the floor or a neighbour touches it


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--build", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--ranks", default="1:1")
    p.add_argument("--rest", action="store_true", help="also check the rest state at the end")
    a = p.parse_args()
    fr, dr = (int(x) for x in a.ranks.split(":"))
    wall, _ = run.run(a.build, a.scene, fr, dr, timeout=600)

    s = io.load_scene(a.scene)
    f = s["fluid"]
    d = s["shapes"][0]["diameter"]
    r = d / 2
    rho_p = s["bodies"][0]["density"]
    mu = f["viscosity"] * f["density"]
    g = -s["dem"]["gravity"][2]
    u_stokes = (rho_p - f["density"]) * g * d * d / (18 * mu)
    hi = np.array(f["domain"])

    t = io.Trace(io.trace_path(a.scene, s))
    x = t.vectors("")   # (T, N, 3)
    v = t.vectors("v")
    n_t, n_b = x.shape[0], x.shape[1]
    failures = []

    def check(ok, text):
        print(("ok:     " if ok else "FAILED: ") + text)
        if not ok:
            failures.append(text)

    check(n_b == 27 and n_t >= int(round(s["time"]["end"] / s["coupling"]["output_interval"])),
          f"{n_b} bodies, {n_t} output times")
    pair = max(d - np.linalg.norm(x[:, i] - x[:, j], axis=1).min()
               for i, j in itertools.combinations(range(n_b), 2))
    wall_gap = np.minimum(x - 0.0, hi - x).min()  # smallest centre-to-wall distance
    check(pair <= MAX_OVERLAP * d,
          f"largest sphere-sphere overlap {pair / d:+.4f} d (bound {MAX_OVERLAP} d)")
    check(r - wall_gap <= MAX_OVERLAP * d,
          f"largest sphere-wall overlap {(r - wall_gap) / d:+.4f} d (bound {MAX_OVERLAP} d); "
          "every body inside the box")
    check(np.isfinite(x).all() and np.isfinite(v).all(), "positions and velocities finite")

    w = (t.time >= WINDOW[0]) & (t.time <= WINDOW[1])
    low = x[w, :, 2].min()
    check(low > r + 0.05 * d, f"no body near the floor in the window (lowest centre "
          f"{low * 1e3:.3f} mm)")
    speed = -v[w, :, 2].mean()
    ratio = speed / u_stokes
    check(SPEED_BAND[0] <= ratio <= SPEED_BAND[1],
          f"mean settling speed over t = {WINDOW[0]}-{WINDOW[1]} s {speed * 1e3:.3f} mm/s = "
          f"{ratio:.3f} of the Stokes speed {u_stokes * 1e3:.2f} mm/s (band {SPEED_BAND[0]} - "
          f"{SPEED_BAND[1]})")
    drift = np.abs(v[w, :, :2].mean(axis=(0, 1))).max() / u_stokes
    print(f"info:   mean horizontal velocity in the window {drift:.3e} of the Stokes speed")

    if a.rest:
        speeds = np.linalg.norm(v[-1], axis=1) / u_stokes
        check(speeds.mean() <= REST_SPEED, f"mean speed at t = {t.time[-1]:.3g} s "
              f"{speeds.mean():.3e} of the Stokes speed (bound {REST_SPEED})")
        print(f"info:   median speed {np.median(speeds):.3e}, largest {speeds.max():.3e} of the "
              "Stokes speed")
        dist = np.linalg.norm(x[-1][:, None, :] - x[-1][None, :, :], axis=2)
        np.fill_diagonal(dist, np.inf)
        supported = (x[-1][:, 2] - r <= CONTACT_GAP * d) | ((dist - d).min(axis=1) <= CONTACT_GAP * d)
        on_floor = int((x[-1][:, 2] - r <= CONTACT_GAP * d).sum())
        check(supported.all(), f"every body rests on the floor or another body "
              f"({on_floor} on the floor, {int((~supported).sum())} unsupported)")
    # The same numbers as lines for tools/validation_table.py.
    tag = f"[validation] closed box, 27 spheres, ranks {a.ranks}:"
    run_time = f"(run time {wall:.1f} s, {fr + dr} ranks)"
    print(f"{tag} largest overlap / d error {max(pair, r - wall_gap) / d:.3e}, tolerance "
          f"{MAX_OVERLAP:.1e} {run_time}")
    print(f"{tag} mean settling speed / Stokes speed, band error {ratio:.3f}, tolerance "
          f"{SPEED_BAND[0]}-{SPEED_BAND[1]} {run_time}")
    print(f"closed box, 27 spheres, ranks {a.ranks}: wall time {wall:.1f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
