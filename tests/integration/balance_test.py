"""The balanced decomposition on a settled bed (configs/bench/bed64_c27.yaml: 64 cubes in the
lower half of a walled box), fluid 8 : DEM 1 ranks, once regular and once balanced. The work
counted per rank at the end of the run (cells + (covered_cell_weight - 1) x covered cells,
docs/scaling.md) must be within 15 % of the mean on every rank with the balanced cuts, and the
regular split must be worse than that (the upper ranks hold plain fluid only). Both runs must
cover the same cells in total. Counters, not wall time: the figures are exact.

Usage: balance_test.py BUILD_DIR SOURCE_DIR
"""
import os
import shutil
import sys
import tempfile

build, src = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
sys.path.insert(0, os.path.join(src, "tools"))
from lbdem import run  # noqa: E402
from lbdem.rundir import Run  # noqa: E402

work = tempfile.mkdtemp()
try:
    figures = {}
    for kind in ("regular", "balanced"):
        folder = os.path.join(work, kind)
        os.makedirs(folder)
        scene = run.bench_scene_copy(src, "bed64_c27.yaml", folder,
                                     [("decomposition: regular", f"decomposition: {kind}")])
        run.execute(run.coupled_command(build, scene, 8, 1), scene, timeout=300)
        s = Run(scene, build).summary("fluid")
        work_per_rank = s["per_rank"]["weighted_work"]["values"]
        covered = sum(s["per_rank"]["covered_cells"]["values"])
        imbalance = max(work_per_rank) / (sum(work_per_rank) / len(work_per_rank))
        figures[kind] = (imbalance, covered)
        print(f"{kind}: weighted work per rank {[int(w) for w in work_per_rank]}, "
              f"imbalance (max/mean) {imbalance:.3f}, covered cells {covered}")
    assert figures["regular"][1] == figures["balanced"][1], figures
    assert figures["balanced"][0] <= 1.15, figures
    assert figures["regular"][0] > 1.15, figures
    print(f"PASS: imbalance {figures['regular'][0]:.3f} regular -> {figures['balanced'][0]:.3f} "
          "balanced")
finally:
    shutil.rmtree(work, ignore_errors=True)
