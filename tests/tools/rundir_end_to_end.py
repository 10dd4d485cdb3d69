"""Opening a run from a script (tools/lbdem/rundir.py), on a real run: the 8-cube quick scene
at fluid 2 : DEM 1 ranks in a temporary folder, then the user guide's three lines. Checks that
the two run summaries agree with each other and with the scene (steps, ranks, how it ended),
that the per-rank cells add up to the lattice, and that the trace holds every body.

Usage: rundir_end_to_end.py BUILD_DIR SOURCE_DIR
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
    scene = run.bench_scene_copy(src, "quick_cubes8_c27.yaml", work)
    os.environ["LBDEM_BUILD"] = build
    run.execute(run.coupled_command(build, scene, 2, 1), scene, timeout=300)

    r = Run(scene, build)
    fluid, dem = r.summary("fluid"), r.summary("dem")
    for s in (fluid, dem):
        assert s["end"] == "completed" and s["exit_status"] == 0, s
        assert s["steps"]["last"] == s["steps"]["schedule"] == 21, s["steps"]
        assert s["ranks"] == {"fluid": 2, "dem": 1}, s["ranks"]
        assert s["scene_fingerprint"] == fluid["scene_fingerprint"]
    cells = fluid["per_rank"]["cells"]
    assert len(cells["values"]) == 2 and sum(cells["values"]) == 29 ** 3, cells
    assert dem["per_rank"]["bodies_owned"]["values"] == [8], dem["per_rank"]
    assert fluid["load_imbalance"]["max_over_mean"] >= 1.0
    assert r.trace.id.tolist() == list(range(8)), r.trace.id
    assert r.trace.vectors("v").shape == (len(r.trace.time), 8, 3)
    assert r.trace.time[-1] > 0
    print(f"run opened: {len(r.trace.time)} trace times, fluid busy per step "
          f"{fluid['per_rank']['busy_s_per_step']['values']}, imbalance "
          f"{fluid['load_imbalance']['max_over_mean']:.3f}")
finally:
    shutil.rmtree(work, ignore_errors=True)
