"""The stability study (docs/stability.md): each scene of configs/stability/ is checked with
--check on the programs it needs, then run through the real entry point, and its outcome is
classed as

  runs       exit 0, every body's trace finite; the case's error is measured
  refused    --check exits 1 with a message (the message says what to change)
  diagnosed  the run stops with exit 3 (fluid stability watch) or 1 with a message naming
             the cause; never silently
  nan        exit 0 but a non-finite number in an output      (a failure of the study)
  crash      any other exit status, or a signal               (a failure)
  hang       no exit within the time limit                    (a failure)
"""
import math
import os
import re
import subprocess
import time

from . import io, references, run
from . import scene as lbdem_scene

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.normpath(os.path.join(HERE, "..", "..", "configs", "stability"))
BASE = "base_sphere_d4"

# name: (expected outcome, fluid:DEM ranks ("" for fluid only), error measure)
CASES = {
    "base_sphere_d4": ("runs", "1:1", "none"),
    "tau_0p51": ("runs", "1:1", "vs_base"),
    "tau_0p505": ("runs", "1:1", "vs_base"),
    "tau_0p501": ("refused", "1:1", "none"),
    "tau_low_for_mach": ("runs", "", "fluid_validation"),
    "mach_0p1": ("runs", "", "fluid_validation"),
    "mach_0p2": ("runs", "", "fluid_validation"),
    "mach_0p3": ("runs", "", "fluid_validation"),
    "mach_0p4": ("diagnosed", "", "none"),
    "mach_0p4_declared": ("refused", "", "none"),
    "cube_re200": ("runs", "1:1", "terminal_hl"),
    "density_1p01": ("runs", "1:1", "uz"),
    "density_1p1": ("runs", "1:1", "uz"),
    "density_0p5": ("runs", "1:1", "uz"),
    "density_0p1": ("refused", "1:1", "none"),
    "contacts_stiff_1gpa": ("runs", "1:1", "pair"),
    "contacts_soft": ("runs", "1:1", "overlap"),
    "impact_wall_fast": ("runs", "1:1", "overlap"),
    "impact_wall_too_fast": ("diagnosed", "1:1", "none"),
    "impact_bodies": ("runs", "1:1", "pair"),
    "periodic_rank_crossing": ("runs", "3:1", "travel"),
    "packing_phi05": ("runs", "1:1", "none"),
    "body_3_cells": ("runs", "1:1", "vs_base"),
    "dem_dt_too_large": ("diagnosed", "1:1", "none"),
    "output_interval_below_step": ("runs", "1:1", "rows_per_step"),
}
VALIDATION = re.compile(r"L2 relative velocity error (\S+),")

# The bound on each case's computed error (the measure of CASES), about 1.5-2x the value
# measured (docs/stability.md, "Outcomes"; policy:
# docs/testing.md "Tolerance policy"). A case that computes a number must stay within its
# bound; a case whose measure yields no number (finite-only checks, refusals, diagnoses) has
# none.
BOUNDS = {
    "tau_0p51": 0.3,                # |u_z - u_z,base| / |u_z,base|, measured 0.19
    "tau_0p505": 0.35,              # measured 0.207
    "tau_low_for_mach": 0.015,      # L2 error against analytic Couette, measured 0.00881
    "mach_0p1": 1.5e-3,             # measured 9.7e-4
    "mach_0p2": 1.5e-3,             # measured 9.7e-4
    "mach_0p3": 1.5e-3,             # measured 9.7e-4
    "cube_re200": 0.25,             # against Haider-Levenspiel far outside its range, 0.15
    "contacts_stiff_1gpa": 2e-3,    # largest overlap / d, measured 0 (docs: below 1e-3)
    "contacts_soft": 0.8,           # overlap / radius at E = 10 Pa, measured 0.531
    "impact_wall_fast": 0.01,       # overlap / radius, measured 0 (the film stops it)
    "impact_bodies": 0.06,          # largest overlap / d, measured 0.0371
    "periodic_rank_crossing": 5e-9,  # travel against v t, measured 2.81e-9
    "body_3_cells": 0.3,            # against the d = 4 baseline, measured 0.188
}
# What a refusal or a diagnosis must say (not any exit 1 or 3 with some text).
MESSAGES = {
    "tau_0p501": r"too close to 1/2",
    "mach_0p4": r"unstable",
    "mach_0p4_declared": r"Mach",
    "density_0p1": r"density",
    "impact_wall_too_fast": r"unstable",
    "dem_dt_too_large": r"unstable",
}


def judge(row):
    """(ok, why) of a study row: the expected outcome, the error within its bound, the
    message of a refusal or diagnosis naming the cause."""
    name = row["case"]
    if row["outcome"] != row["expected"]:
        return False, "MISMATCH"
    bound = BOUNDS.get(name)
    if bound is not None:
        if row["error"] is None or not math.isfinite(row["error"]):
            return False, f"no error computed (bound {bound:g})"
        if row["error"] > bound:
            return False, f"error {row['error']:.3g} above its bound {bound:g}"
    pattern = MESSAGES.get(name)
    if pattern and not re.search(pattern, row.get("output") or row["message"]):
        return False, f"the message does not say '{pattern}'"
    return True, ""


def scene_path(name):
    return os.path.join(SCENES, name + ".yaml")


def check(build, name, fluid_only):
    """(refused?, message) from --check of each program the scene needs."""
    apps = ["fluid_app"] if fluid_only else ["fluid_app", "dem_app"]
    for app in apps:
        exe = os.path.abspath(os.path.join(build, app, app))
        p = subprocess.run(run.mpirun() + ["-np", "1", exe, "--check", scene_path(name)],
                           env=run.environment(), capture_output=True, text=True, timeout=120,
                           cwd=SCENES)
        if p.returncode != 0:
            return True, f"{app}: " + last_error(p.stdout + p.stderr)
    return False, ""


def last_error(text):
    """The message lines of a refusal or a diagnosis (without mpirun's own trailer)."""
    keep = [ln.strip() for ln in text.splitlines()
            if ln.strip() and not ln.startswith(("-----", "mpirun", "Primary job", "process",
                                                 "Process name", "Exit code", "prterun"))
            and ("error" in ln.lower() or "unstable" in ln.lower() or "refus" in ln.lower()
                 or "likely cause" in ln or "must" in ln or "change" in ln.lower())]
    return " / ".join(keep[-4:]) if keep else text.strip().splitlines()[-1] if text.strip() else ""


def launch(build, name, ranks, timeout):
    """(exit status or None on timeout, output, wall)."""
    path = scene_path(name)
    if ranks:
        fr, dr = (int(x) for x in ranks.split(":"))
        cmd = run.coupled_command(build, path, fr, dr)
    else:
        cmd = run.mpirun() + ["-np", "1", os.path.abspath(os.path.join(build, "fluid_app",
                                                                       "fluid_app")), path]
    start = time.monotonic()
    try:
        p = subprocess.run(cmd, env=run.environment(), stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, timeout=timeout, cwd=SCENES)
    except subprocess.TimeoutExpired as e:
        return None, (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) \
            else (e.stdout or ""), time.monotonic() - start
    return p.returncode, p.stdout, time.monotonic() - start


def trace(name):
    path = io.trace_path(scene_path(name))
    return io.read_trace_by_body(path) if os.path.exists(path) else {}


def finite(bodies):
    return all(math.isfinite(v) for rows in bodies.values() for r in rows for v in r.values())


def error_of(name, measure, output, bodies):
    """(value, what) of the case's error measure."""
    s = io.load_scene(scene_path(name))
    if measure == "fluid_validation":
        m = VALIDATION.search(output)
        return (float(m.group(1)), "L2 error vs analytic Couette") if m else (None, "")
    if measure == "vs_base":
        base = trace(BASE)
        if not base:
            return None, "baseline not run"
        u0 = base[0][-1]["vz"]
        u = bodies[0][-1]["vz"]
        return abs(u - u0) / abs(u0), f"u_z(t_end) {u:.4g} m/s vs baseline {u0:.4g} m/s"
    if measure == "uz":
        return None, f"u_z(t_end) = {bodies[0][-1]['vz']:.4g} m/s (finite, no divergence)"
    if measure == "overlap":
        r = s["shapes"][0]["diameter"] / 2
        lowest = min(row["z"] for row in bodies[0])
        return max(0.0, r - lowest) / r, "largest overlap with the floor / radius"
    if measure == "terminal_hl":
        sh, b = s["shapes"][0], s["bodies"][0]
        f = s["fluid"]
        ref = references.haider_levenspiel_velocity(
            references.cube_volume_equivalent_diameter(sh["edge"]), references.CUBE_SPHERICITY,
            f["density"], b["density"], f["density"] * f["viscosity"])
        # The plateau speed: the cube lands on the floor near the end of the run.
        u = max(-r["vz"] for r in bodies[0])
        return abs(u - ref) / ref, (f"plateau u {u:.4g} m/s vs Haider-Levenspiel {ref:.4g} m/s "
                                    f"(Re {u * 1.24e-3 / f['viscosity']:.0f})")
    if measure == "rows_per_step":
        steps = lbdem_scene.resolve(None, scene_path(name))["derived"]["schedule"]["steps"]
        return None, f"{len(bodies[0])} trace rows for {steps} steps"
    if measure == "pair":
        d = s["shapes"][0]["diameter"]
        gaps = [abs(b["z"] - a["z"]) - d for a, b in zip(bodies[0], bodies[1])]
        rel = [b["vz"] - a["vz"] for a, b in zip(bodies[0], bodies[1])]
        return max(0.0, -min(gaps)) / d, (f"largest overlap / d; relative speed "
                                          f"{rel[0]:.3g} -> {rel[-1]:.3g} m/s")
    if measure == "travel":
        rows = bodies[0]
        v = s["bodies"][0]["velocity"][0]
        lx = s["fluid"]["domain"][0]
        moved = rows[-1]["x"] - rows[0]["x"]
        expect = v * (rows[-1]["time"] - rows[0]["time"])
        # Positions are wrapped into the box: unwrap by whole box lengths.
        moved -= round((moved - expect) / lx) * lx
        return abs(moved - expect) / abs(expect), f"travel {moved:.4g} m vs v t {expect:.4g} m"
    return None, ""


def study_case(build, name, timeout=300, log_dir=None):
    """Runs one case; returns its row (outcome, message, error, wall). With log_dir, the run's
    output is kept in <log_dir>/<name>.log."""
    expected, ranks, measure = CASES[name]
    row = {"case": name, "expected": expected, "ranks": ranks or "1 (fluid only)",
           "error": None, "what": "", "wall_s": 0.0}
    refused, msg = check(build, name, not ranks)
    if refused:
        row.update(outcome="refused", message=msg)
        return row
    status, output, wall = launch(build, name, ranks, timeout)
    row["wall_s"] = wall
    row["output"] = output
    if log_dir:
        with open(os.path.join(log_dir, name + ".log"), "w") as out:
            out.write(output)
    if status is None:
        row.update(outcome="hang", message=f"no exit within {timeout} s")
        return row
    if status == 0:
        bodies = trace(name) if ranks else {}
        nan = re.search(r"\bnan\b|\binf\b", output, re.I) is not None
        if not finite(bodies) or nan:
            row.update(outcome="nan", message="non-finite number in the output")
            return row
        err, what = error_of(name, measure, output, bodies)
        row.update(outcome="runs", message="", error=err, what=what)
        return row
    text = last_error(output)
    if status in (1, 3) and text:
        row.update(outcome="diagnosed", message=f"exit {status}: {text}")
    else:
        row.update(outcome="crash", message=f"exit {status}: {output.strip()[-600:]}")
    return row
