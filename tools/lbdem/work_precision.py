"""Error against run time for the validation cases (docs/work-precision.md).

A case is a validation scene plus the quantity it is judged by and its reference. A ladder
runs it at several resolutions n (cells across the body's size; the box, the body and the
physics stay, only dx changes) and, where the result depends on it, several tau. Each rung
records the relative error, the wall time, the cell updates (cells x steps), the ranks, the
hydrodynamic radius (calibrated, the default, or nominal) and the build that ran it. A ladder
is one (case, tau, radius). From the rungs: the observed order (least squares of log error on
log n, and between neighbours), the cost law wall ~ n^p, the next rung's cost and error
extrapolated, and the error reachable in 1 min / 10 min / 1 h of this machine (log error
interpolated on log wall along each ladder; beyond the last rung it follows the two fits, and
is marked so).
"""
import copy
import csv
import math
import os

import yaml

from . import io, references, run
from . import scene as lbdem_scene

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
COUPLED = os.path.join(ROOT, "configs", "validation", "coupled")

# name: (scene, measure, reference (None: computed from the run's scene), ladder n, taus).
# n counts cells across the body's size (sphere diameter, cube edge). Each base scene's header
# cites the published number.
CASES = {
    "sphere_terminal": ("sphere_terminal_d6_tau06.yaml", "terminal",
                        references.SPHERE_TERMINAL_VELOCITY, [4, 6, 8, 12], [0.6, 0.8]),
    # The cube: the paper's value at its finest resolution (the scene's header; Haider &
    # Levenspiel give 0.0438 m/s).
    "cube_terminal": ("cube_terminal_a5_tau06.yaml", "terminal", 0.0457, [4, 5, 7], [0.6]),
    "tencate_e1": ("tencate_e1_r3.yaml", "peak", references.TEN_CATE["E1"]["u_max"],
                   [4, 6, 9, 12], [0.661]),
    "tencate_e4": ("tencate_e4_r4p5.yaml", "peak", references.TEN_CATE["E4"]["u_max"],
                   [6, 9, 12], [0.6]),
    "drag_array": ("drag_array_phi0064.yaml", "drag", None, [6, 8, 12], [0.8]),
    "sphere_spin": ("sphere_spin.yaml", "spin", None, [6, 8, 12], [0.8]),
}
# An observed order above this is not the asymptotic convergence of a scheme of formal order 2
# (the lattice Boltzmann bulk; the body's surface is first order): the error is passing through
# zero or reaching its floor (a calibrated radius does both), and no law is extrapolated from it.
MAX_ORDER = 2.5
WINDOW = 0.2  # the last fifth of a run is averaged for terminal speed, drag and torque
BUDGETS = [("1 min", 60.0), ("10 min", 600.0), ("1 h", 3600.0)]


def body_size(scene):
    sh = scene["shapes"][0]
    return sh.get("diameter") or sh.get("edge")


def rung_scene(base_path, n, tau, out_dir, end=None, radius="calibrated"):
    """The base scene at n cells across the body, tau and fluid.hydrodynamic_radius given;
    outputs go to out_dir. Axes that are not whole cells at the new dx are rounded to the
    nearest whole number of cells (the change is returned as the largest relative change of a
    box edge)."""
    values = io.load_scene(base_path)
    scene = copy.deepcopy(io.read_scene_yaml(base_path))
    f = scene["fluid"]
    dx = body_size(values) / n
    old = [float(v) for v in values["fluid"]["domain"]]
    f.pop("resolution", None)  # replaced by dx
    f["domain"] = [max(1, round(v / dx)) * dx for v in old]
    f["dx"] = dx
    f["tau"] = tau
    f["hydrodynamic_radius"] = radius
    scene["name"] = f"{scene['name']}_n{n:g}_tau{tau:g}_{radius}"
    if end:
        scene["time"]["end"] = end
    scene["dem"].setdefault("output", {})["directory"] = out_dir
    if "output" in f:
        f["output"]["directory"] = out_dir
    change = max(abs(a - b) / b for a, b in zip(f["domain"], old))
    return scene, change


def tail(rows, key, window=WINDOW):
    t_end = rows[-1]["time"]
    vals = [r[key] for r in rows if r["time"] >= (1 - window) * t_end]
    return sum(vals) / len(vals)


def measure(kind, scene_path, scene):
    """(result, reference) of a finished run; the reference None means "from the scene"."""
    bodies = io.read_trace_by_body(io.trace_path(scene_path, scene))
    rows = bodies[min(bodies)]
    f = scene["fluid"]
    if kind == "terminal":
        return -tail(rows, "vz"), None
    if kind == "peak":
        return max(-r["vz"] for r in rows), None
    a = body_size(scene) / 2
    mu = f["density"] * f["viscosity"]
    if kind == "spin":
        w = scene["bodies"][0]["angular_velocity"][2]
        return -tail(rows, "tz"), 8 * math.pi * mu * a ** 3 * w
    if kind == "drag":
        # K = rho g L^3 / (6 pi mu a U) against Sangani & Acrivos, as validate_case.py drag.
        series = io.read_rows(io.series_path(scene_path, scene))
        t_end = series[-1]["time_s"]
        us = [r["mean_uz_m_s"] for r in series if r["time_s"] >= (1 - WINDOW) * t_end]
        u = abs(sum(us) / len(us))
        box = math.prod(f["domain"])
        phi = 4.0 / 3.0 * math.pi * a ** 3 / box
        k = f["density"] * abs(f["body_force"][2]) * box / (6 * math.pi * mu * a * u)
        return k, references.sangani_acrivos_k(phi)
    raise ValueError(f"unknown measure {kind}")


def run_rung(build, case, n, tau, work, ranks=(1, 1), end=None, timeout=3600,
             radius="calibrated"):
    """Writes the rung's scene under work/, runs it, returns its row."""
    base, kind, reference = CASES[case][:3]
    base_path = os.path.join(COUPLED, base)
    folder = os.path.join(os.path.abspath(work), case)
    os.makedirs(folder, exist_ok=True)
    scene, change = rung_scene(base_path, n, tau, ".", end, radius)
    path = os.path.join(folder, scene["name"] + ".yaml")
    with open(path, "w") as out:
        yaml.safe_dump(scene, out, sort_keys=False)
    wall, _ = run.run(build, path, ranks[0], ranks[1], timeout=timeout,
                      log=os.path.join(folder, scene["name"] + ".log"))
    # Values as the programs read the scene written above (lbdem/scene.py).
    resolved = lbdem_scene.resolve(build, path)
    result, ref = measure(kind, path, resolved["scene"])
    ref = reference if ref is None else ref
    steps = resolved["derived"]["schedule"]["steps"]
    cells = int(resolved["derived"]["fluid"]["cell_count"])
    return {"case": case, "n": n, "tau": tau, "cells": cells, "steps": steps,
            "cell_updates": cells * steps, "ranks": f"{ranks[0]}:{ranks[1]}",
            "result": result, "reference": ref, "error": abs(result - ref) / abs(ref),
            "wall_s": wall, "box_change": change, "end_s": scene["time"]["end"],
            "radius": radius, "build": run.build_id(build)}


def fit(xs, ys):
    """Least-squares slope and intercept of log y on log x."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((x - mx) ** 2 for x in lx)
    slope = sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / sxx if sxx > 0 else 0.0
    return slope, my - slope * mx


def analyse(rows):
    """Per ladder (case, tau, radius): pairwise orders on the rows, the fits, the extrapolated
    next rung and the error at each budget. Returns {(case, tau, radius): summary}."""
    out = {}
    for key in sorted({ladder_key(r) for r in rows}):
        ladder = sorted((r for r in rows if ladder_key(r) == key), key=lambda r: r["n"])
        for a, b in zip(ladder, ladder[1:]):
            b["order"] = math.log(a["error"] / b["error"]) / math.log(b["n"] / a["n"])
        s = {"rows": ladder}
        if len(ladder) >= 2:
            ns = [r["n"] for r in ladder]
            order, c_err = fit(ns, [r["error"] for r in ladder])
            p, c_wall = fit(ns, [r["wall_s"] for r in ladder])
            s.update(order=-order, cost_power=p)
            n_next = ns[-1] * 1.5
            s["next"] = {"n": n_next, "wall_s": math.exp(c_wall) * n_next ** p,
                         "error": math.exp(c_err) * n_next ** order
                         if extrapolable(-order) else None}
            s["budget"] = {}
            for label, budget in BUDGETS:
                s["budget"][label] = error_at(ladder, budget, order, c_err, p, c_wall)
        out[key] = s
    return out


def extrapolable(order):
    return 0 < order <= MAX_ORDER


def ladder_key(row):
    return row["case"], row["tau"], row["radius"]


def error_at(ladder, budget, slope, c_err, p, c_wall):
    """(error, how) reachable with `budget` seconds of wall: interpolated between rungs, or from
    the fits beyond them ("extrapolated"), or "below the first rung"."""
    walls = [r["wall_s"] for r in ladder]
    if budget < walls[0]:
        return None, "below the first rung"
    for a, b in zip(ladder, ladder[1:]):
        if a["wall_s"] <= budget <= b["wall_s"] and b["wall_s"] > a["wall_s"]:
            w = math.log(budget / a["wall_s"]) / math.log(b["wall_s"] / a["wall_s"])
            return math.exp((1 - w) * math.log(a["error"]) + w * math.log(b["error"])), "measured"
    if p <= 0:
        return ladder[-1]["error"], "last rung"
    if slope >= 0:
        return None, "not extrapolated: the error does not fall with n"
    if not extrapolable(-slope):
        return None, f"not extrapolated: order {-slope:.2g} is above {MAX_ORDER:g}"
    n = (budget / math.exp(c_wall)) ** (1 / p)
    return math.exp(c_err) * n ** slope, f"extrapolated (n = {n:.3g})"


FIELDS = ["case", "n", "tau", "radius", "cells", "steps", "cell_updates", "ranks", "result",
          "reference", "error", "order", "wall_s", "box_change", "end_s", "build"]


def write_csv(path, rows):
    with open(path, "w", newline="") as out:
        w = csv.DictWriter(out, fieldnames=FIELDS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: ("" if r.get(k) is None else r.get(k)) for k in FIELDS})


def read_csv(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            row = {k: r[k] for k in ("case", "ranks")}
            # A CSV written before these columns: its radius is unknown and its rows are never
            # reused (no build).
            row["radius"] = r.get("radius") or "unknown"
            row["build"] = r.get("build") or ""
            for k in ("n", "tau", "result", "reference", "error", "wall_s", "box_change", "end_s"):
                row[k] = float(r[k])
            for k in ("cells", "steps", "cell_updates"):
                row[k] = int(r[k])
            rows.append(row)
    return rows


def plot(case, summaries, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for (c, tau, radius), s in summaries.items():
        if c != case:
            continue
        rows = s["rows"]
        line, = ax.loglog([r["wall_s"] for r in rows], [r["error"] for r in rows], "o-",
                          label=f"tau = {tau:g}, {radius} radius")
        for r in rows:
            ax.annotate(f"n={r['n']:g}", (r["wall_s"], r["error"]), fontsize=7)
        if "next" in s and s["next"]["error"] is not None:
            nx = s["next"]
            ax.loglog([rows[-1]["wall_s"], nx["wall_s"]], [rows[-1]["error"], nx["error"]], "--",
                      color=line.get_color())
            ax.loglog([nx["wall_s"]], [nx["error"]], "o", mfc="none", color=line.get_color())
    for label, b in BUDGETS:
        ax.axvline(b, color="grey", lw=0.5)
    ax.set_xlabel("wall time of the run [s] (this machine)")
    ax.set_ylabel("relative error against the reference")
    ax.set_title(f"{case}: error against run time\n(dashed, open marker: next rung, extrapolated)",
                 fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def markdown(summaries):
    lines = ["| case | tau | radius | n | cells | steps | result | error | order | wall (s) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for (case, tau, radius), s in summaries.items():
        for r in s["rows"]:
            o = f"{r['order']:.2f}" if r.get("order") is not None else "-"
            lines.append(f"| {case} | {tau:g} | {radius} | {r['n']:g} | {r['cells']} | "
                         f"{r['steps']} | {r['result']:.5g} | {100 * r['error']:.2f} % | {o} | "
                         f"{r['wall_s']:.1f} |")
    lines += ["", "| case | tau | radius | fitted order | wall ~ n^p | "
              "next rung (n, wall, error) | "
              + " | ".join(f"error at {label}" for label, _ in BUDGETS) + " |",
              "|---|---|---|---|---|---|" + "---|" * len(BUDGETS)]
    for (case, tau, radius), s in summaries.items():
        if "order" not in s:
            continue
        nx = s["next"]
        nx_err = "not extrapolated" if nx["error"] is None else f"{100 * nx['error']:.2g} %"
        cells = []
        for label, _ in BUDGETS:
            e, how = s["budget"][label]
            cells.append(how if e is None else f"{100 * e:.2g} % ({how})")
        lines.append(f"| {case} | {tau:g} | {radius} | {s['order']:.2f} | {s['cost_power']:.2f} | "
                     f"{nx['n']:.3g}, {nx['wall_s']:.3g} s, {nx_err} | "
                     + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"
