"""The balanced decomposition on a settled bed (configs/bench/bed64_c27.yaml: 64 cubes in the
lower half of a walled box), fluid 8 : DEM 1 ranks: once regular, once balanced by the initial
bodies, and once regular up to a checkpoint, then continued with decomposition: balanced, which
cuts the lattice anew by the work measured at the checkpoint (fluid_app/parallel/rebalance.hpp).
The work counted per rank at the end of each run (cells + (covered_cell_weight - 1) x covered
cells, docs/scaling.md) must be within 15 % of the mean on every rank with balanced cuts, and
the regular split must be worse than that (the upper ranks hold plain fluid only). The first two
runs must cover the same cells in total. Counters, not wall time: the figures are exact.

Every run is 2 fluid steps long (the continued one 2 more). Usage:
balance_test.py BUILD_DIR SOURCE_DIR [BENCH_SCENE]   (default bed64_c27.yaml; with another
scene of configs/bench, e.g. the suspension cubes125_c27.yaml, the regular split is not required
to be worse)
"""
import os
import re
import shutil
import sys
import tempfile

build, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
bench = sys.argv[3] if len(sys.argv) > 3 else "bed64_c27.yaml"
sys.path.insert(0, os.path.join(src, "tools"))
from lbdem import run  # noqa: E402
from lbdem.rundir import Run  # noqa: E402


def two_steps(scene):
    """Simulated time of 2 fluid steps, dt = (tau - 1/2) / 3 dx^2 / nu (docs/method.md)."""
    with open(scene) as f:
        text = f.read()
    value = {k: float(re.search(rf"(?m)^  {k}: ([0-9.e+-]+)", text).group(1))
             for k in ("dx", "tau", "viscosity")}
    return 2 * (value["tau"] - 0.5) / 3 * value["dx"] ** 2 / value["viscosity"]


def scene_copy(folder, kind, end, checkpoint=None):
    scene = run.bench_scene_copy(src, bench, folder)
    with open(scene) as f:
        text = f.read()
    text = re.sub(r"(?m)^fluid:\n", f"fluid:\n  decomposition: {kind}\n", text.replace(
        "  decomposition: regular\n", ""))
    text = re.sub(r"time: \{end: [0-9.e+-]+", f"time: {{end: {end!r}", text)
    if checkpoint is not None:
        text = text.replace("\ncoupling:\n", "\ncoupling:\n  checkpoint_interval: "
                            f"{checkpoint!r}\n") if "\ncoupling:\n" in text else \
            text.replace("\nbodies:\n", f"\ncoupling: {{checkpoint_interval: {checkpoint!r}}}"
                         "\nbodies:\n")
    with open(scene, "w") as f:
        f.write(text)
    return scene


def figures_of(scene):
    s = Run(scene, build).summary("fluid")
    work_per_rank = s["per_rank"]["weighted_work"]["values"]
    covered = sum(s["per_rank"]["covered_cells"]["values"])
    return max(work_per_rank) / (sum(work_per_rank) / len(work_per_rank)), covered, work_per_rank


work = tempfile.mkdtemp()
try:
    end = two_steps(run.bench_scene_copy(src, bench, work))  # every run: 2 steps
    figures = {}
    for kind in ("regular", "balanced"):
        folder = os.path.join(work, kind)
        os.makedirs(folder)
        scene = scene_copy(folder, kind, end)
        run.execute(run.coupled_command(build, scene, 8, 1), scene, timeout=300)
        figures[kind] = figures_of(scene)
    # Regular up to a checkpoint at the scene's end, then continued balanced for as long again.
    folder = os.path.join(work, "rebalanced")
    os.makedirs(folder)
    first = scene_copy(folder, "regular", end, checkpoint=end)
    run.execute(run.coupled_command(build, first, 8, 1), first, timeout=300)
    second = scene_copy(folder, "balanced", 2 * end, checkpoint=end)
    cmd = run.coupled_command(build, second, 8, 1)
    restart = os.path.join(folder, "out", os.path.splitext(bench)[0] + "_checkpoints")
    at = cmd.index(second)
    cmd[at:at] = ["--restart", restart]
    at = len(cmd) - 1
    cmd[at:at] = ["--restart", restart]
    _, out = run.execute(cmd, second, timeout=300)
    print(re.search(r"decomposition .*", out).group(0))
    # The bed's regular split is far above fluid.rebalance_above: the restart must recut.
    if bench == "bed64_c27.yaml" and "rebalanced by the work measured" not in out:
        print(out)
        raise SystemExit("FAIL: the restart did not rebalance")
    figures["rebalanced at the restart"] = figures_of(second)
    for kind, (imbalance, covered, per_rank) in figures.items():
        print(f"{kind}: weighted work per rank {[int(w) for w in per_rank]}, "
              f"imbalance (max/mean) {imbalance:.3f}, covered cells {covered}")
    assert figures["regular"][1] == figures["balanced"][1], figures
    assert figures["balanced"][0] <= 1.15, figures
    assert figures["rebalanced at the restart"][0] <= 1.15, figures
    if bench == "bed64_c27.yaml":
        assert figures["regular"][0] > 1.15, figures
    print(f"PASS: imbalance {figures['regular'][0]:.3f} regular -> {figures['balanced'][0]:.3f} "
          f"balanced by the initial bodies, {figures['rebalanced at the restart'][0]:.3f} "
          "rebalanced at a restart by the measured work")
finally:
    shutil.rmtree(work, ignore_errors=True)
