"""Rebalancing during a run (fluid.rebalance_interval, docs/scaling.md) on a dense suspension:
125 cubes on a cubic lattice, phi = 0.31, triply periodic (configs/bench/cubes125_c27.yaml),
fluid 8 : DEM 2 ranks. Cut by the initial bodies' volume-equivalent spheres, its measured
weighted work is out of balance by more than the default fluid.rebalance_above (1.1); at step 2
the fluid measures it, cuts its lattice anew while the run goes on, and the DEM routes the bodies
by the new boxes. 4 fluid steps in all, the body trace written every step.

The log must show the imbalance of the weighted work before the cut (above 1.1) and after it (at
most 1.05, what the end-of-run counter also says), and the body trace must equal within
round-off (the new cuts regroup the partial loads) that of the same run checking at step 2 and
keeping its cuts (fluid.rebalance_above: 100): a check step is an agreement step, where the
overlapped fluid (coupling.overlap, the default) embeds the states of that very step instead of
the step before, as at a checkpoint, so the reference must check at the same steps. The
largest relative difference is printed. Counters, not wall time: the figures are exact.

Another scene of configs/bench may be given (the settled bed bed64_c27.yaml: 64 cubes in the
lower half of a walled box), and a threshold other than the default 1.1.
Usage: rebalance_in_run_test.py BUILD_DIR SOURCE_DIR [FLUID_RANKS DEM_RANKS [SCENE [THRESHOLD]]]
"""
import csv
import os
import re
import shutil
import sys
import tempfile

build, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
nf, nd = (int(sys.argv[3]), int(sys.argv[4])) if len(sys.argv) > 4 else (8, 2)
bench = sys.argv[5] if len(sys.argv) > 5 else "cubes125_c27.yaml"
threshold = float(sys.argv[6]) if len(sys.argv) > 6 else None
sys.path.insert(0, os.path.join(src, "tools"))
from lbdem import run  # noqa: E402
from lbdem.rundir import Run  # noqa: E402


def scene_copy(folder, interval_steps, above=None):
    """The bench scene, balanced, 4 steps, the trace every step; in-run rebalancing every
    `interval_steps` steps (0: none) above `above` (None: the default)."""
    scene = run.bench_scene_copy(src, bench, folder)
    with open(scene) as f:
        text = f.read()
    v = {k: float(re.search(rf"(?m)^  {k}: ([0-9.e+-]+)", text).group(1))
         for k in ("dx", "tau", "viscosity")}
    dt = (v["tau"] - 0.5) / 3 * v["dx"] ** 2 / v["viscosity"]  # docs/method.md
    text = re.sub(r"(?m)^  decomposition: \w+\n", "", text)
    fluid = "fluid:\n  decomposition: balanced\n"
    if interval_steps:
        fluid += f"  rebalance_interval: {interval_steps * dt!r}\n"
    if above is not None:
        fluid += f"  rebalance_above: {above!r}\n"
    text = text.replace("fluid:\n", fluid, 1)
    text = re.sub(r"time: \{end: [0-9.e+-]+", f"time: {{end: {4 * dt!r}", text)
    if re.search(r"(?m)^  output_interval: ", text):
        text = re.sub(r"(?m)^  output_interval: [0-9.e+-]+$", f"  output_interval: {dt!r}", text)
    else:
        text = text.replace("\nbodies:\n", f"\ncoupling: {{output_interval: {dt!r}}}\nbodies:\n")
    with open(scene, "w") as f:
        f.write(text)
    return scene


def trace_rows(scene):
    name = os.path.splitext(bench)[0]
    with open(os.path.join(os.path.dirname(scene), "out", name + "_bodies.csv")) as f:
        return list(csv.reader(f))


work = tempfile.mkdtemp()
try:
    runs = {}
    for name, interval, above in (("kept", 2, 100.0), ("rebalanced", 2, threshold)):
        folder = os.path.join(work, name)
        os.makedirs(folder)
        scene = scene_copy(folder, interval, above)
        _, out = run.execute(run.coupled_command(build, scene, nf, nd), scene, timeout=600)
        runs[name] = (scene, out)
    scene, out = runs["rebalanced"]
    found = re.search(r"step 2: load imbalance of the weighted work ([0-9.]+) -> ([0-9.]+)", out)
    if not found:
        print(out[-6000:])
        raise SystemExit("FAIL: no in-run rebalancing at step 2")
    before, after = float(found.group(1)), float(found.group(2))
    print(re.search(r"decomposition .*rebalanced at step.*", out).group(0))
    print(found.group(0))
    if "the fluid cut its lattice anew" not in out:
        raise SystemExit("FAIL: the DEM side did not take the new boxes")
    work_per_rank = Run(scene, build).summary("fluid")["per_rank"]["weighted_work"]["values"]
    final = max(work_per_rank) / (sum(work_per_rank) / len(work_per_rank))
    print(f"end of the run: weighted work per rank {[int(w) for w in work_per_rank]}, "
          f"imbalance {final:.3f}")
    assert before > (threshold or 1.1), before
    assert after <= 1.05 and abs(final - after) < 0.01, (after, final)
    a, b = trace_rows(runs["kept"][0]), trace_rows(scene)
    assert len(a) == len(b) and len(a) > 4, (len(a), len(b))
    # Per value, relative to itself (as restart_test.sh) and relative to the largest magnitude
    # of its quantity (position, velocity, ..., all three components). A component that is zero
    # by the scene's symmetry holds round-off only (a quaternion's qz of 1.7e-20 beside qw 1):
    # values below 1e-9 of their quantity's largest are left out of the first figure, whose
    # ratio of two round-offs says nothing; the second figure still covers them.
    columns = list(zip(*[[float(x) for x in r] for r in a[1:]]))
    group = ["position" if h in ("x", "y", "z") else h[0] if len(h) == 2 else h for h in a[0]]
    largest = {}
    for g, c in zip(group, columns):
        largest[g] = max(largest.get(g, 0.0), max(abs(v) for v in c))
    scale = [largest[g] or 1.0 for g in group]
    worst, worst_scaled, where = 0.0, 0.0, ""
    for ra, rb in zip(a[1:], b[1:]):
        for k, (x, y) in enumerate(zip(ra, rb)):
            x, y = float(x), float(y)
            worst_scaled = max(worst_scaled, abs(x - y) / scale[k])
            if max(abs(x), abs(y)) > 1e-9 * scale[k]:
                rel = abs(x - y) / max(abs(x), abs(y))
                if rel > worst:
                    worst, where = rel, f"{a[0][k]} {x!r} against {y!r}"
    print(f"body trace against the run keeping its cuts: largest relative "
          f"difference {worst:.3e} ({where}), {worst_scaled:.3e} of its quantity's largest value")
    assert worst < 1e-6 and worst_scaled < 1e-10, (worst, worst_scaled)
    kept = re.search(r"step 2: load imbalance of the weighted work [0-9.]+, at most .*",
                     runs["kept"][1])
    assert kept, runs["kept"][1][-6000:]
    print("reference: " + kept.group(0))
    print(f"PASS: in-run rebalancing ({nf}:{nd}) imbalance {before:.3f} -> {after:.3f}, "
          f"trace within {worst_scaled:.1e} of each quantity's scale")
finally:
    shutil.rmtree(work, ignore_errors=True)
