#!/usr/bin/python3
"""scaling: per-rank counters of coupled runs, weak and strong scaling series on the study's
cube scene, and the cost model of a coupled step (docs/scaling.md).

    /usr/bin/python3 tools/scaling.py [--build build] [--out runs/scaling] [--steps 40]
        [--fit [--fit-repeat 3] [--fit-runs 3]] [--weak 1 2 4 8] [--strong 1 2 4 8]
        [--dem-per-fluid 4] [--predict]
        [--paper configs/study/paper_3150.yaml --packing FILE --ranks 2 1 --steps 300]
    /usr/bin/python3 tools/scaling.py --ci     # ctest: two tiny runs, the counters checked

--fit runs the fit scenes on 1 fluid : 1 DEM rank (and one on 2 : 1 for the halo cost), fits the
per-unit costs (tools/lbdem/scaling.py) and saves them with the measured memory per rank in
<out>/model.json; then checks the model against the 1- and 2-rank points it did not use
(predicted against measured time per step). --fit-repeat K does the same on the fit scenes
repeated K times along each axis (blocks of (58 K)^3 cells, the size a rank of the paper's
systems holds) and saves <out>/model_rK.json, which --predict and --paper then use; --fit-runs
K runs each fit and check scene K times and keeps the least disturbed run (shared cores);
--calibrate RUN scales its fluid costs to a measured run of a paper system. --weak / --strong
run the series (the study's cube scene, configs/bench/cubes64_c27.yaml: 64 cubes of a/dx = 9.7
at phi = 0.3 in 58^3 cells; weak: that cell repeated once per fluid rank; strong: the scene
itself), each point with fluid.decomposition regular and balanced, and print the counters, the
time per step and the load imbalance of both. --predict prints the model's time per step and
memory per rank for the paper's three systems on 16 to 1024 cores. --paper runs a study system
(its cube suspension at phi = 0.3, the packing given) for --steps steps here and prints the
same.
Every figure comes from the run summaries (lbdem.rundir), none from log lines.
"""
import argparse
import copy
import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import io, run, scaling  # noqa: E402
from lbdem.rundir import Run  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BASE = os.path.join(ROOT, "configs", "bench", "cubes64_c27.yaml")
SHAPES = os.path.join(ROOT, "configs", "shapes")
PAPER = {n: os.path.join(ROOT, "configs", "study", f"paper_{n}.yaml")
         for n in (3150, 10648, 103823)}
CORES = (16, 64, 256, 1024)
GLOBAL_BODY_BYTES = 160  # per body on every DEM rank: scene table 120 B + mass, offset 40 B
CLUMP_SPHERES = 27


def base_scene(path=BASE):
    s = io.read_scene_yaml(path)
    s["shapes"][0]["clump"]["file"] = os.path.join(SHAPES, "cube_27_surface.clump")
    s["dem"]["output"] = {"directory": "."}
    return s


def lattice_step(s):
    """dt of the scene's lattice: (tau - 1/2) / 3 dx^2 / nu."""
    f = s["fluid"]
    return (float(f["tau"]) - 0.5) / 3.0 * float(f["dx"]) ** 2 / float(f["viscosity"])


def cells_of(s):
    f = s["fluid"]
    return [round(float(x) / float(f["dx"])) for x in f["domain"]]


def with_steps(s, steps, decomposition="regular"):
    s = copy.deepcopy(s)
    end = steps * lattice_step(s)
    s["time"] = {"end": end, "progress_interval": 1.0e9}
    s["coupling"] = dict(s.get("coupling") or {}, output_interval=end)
    s["fluid"]["decomposition"] = decomposition
    return s


def repeated(s, k):
    """The scene's box and bodies repeated k = (kx, ky, kz) times."""
    s = copy.deepcopy(s)
    box = [float(x) for x in s["fluid"]["domain"]]
    bodies = []
    for i in range(k[0]):
        for j in range(k[1]):
            for m in range(k[2]):
                for b in s["bodies"]:
                    p = [float(b["position"][a]) + (i, j, m)[a] * box[a] for a in range(3)]
                    bodies.append(dict(b, position=p))
    s["fluid"]["domain"] = [box[a] * k[a] for a in range(3)]
    s["bodies"] = bodies
    return s


def thinned(s, scale=1.0):
    """The 8 bodies of the even lattice sites (spacing L/2), edge times `scale`."""
    s = copy.deepcopy(s)
    spacing = float(s["fluid"]["domain"][0]) / 4
    s["bodies"] = [b for b in s["bodies"]
                   if all(round(float(x) / spacing - 0.5) % 2 == 0 for x in b["position"])]
    sh = s["shapes"][0]
    sh["edge"] = float(sh["edge"]) * scale
    sh["clump"]["scale"] = float(sh["clump"]["scale"]) * scale
    return s


def rotated(s, seed=7):
    """The scene's bodies turned to random orientations (uniform quaternions, fixed seed): the
    same covered cells per body as aligned ones, on many more lattice rows."""
    import numpy as np
    s = copy.deepcopy(s)
    rng = np.random.default_rng(seed)
    for b in s["bodies"]:
        q = rng.normal(size=4)
        b["orientation"] = [float(x) for x in q / np.linalg.norm(q)]
    return s


def launch(args, name, scene, fluid, dem, nice=0):
    folder = os.path.join(args.out, name)
    os.makedirs(folder, exist_ok=True)
    scene = dict(scene, name=name)
    path = os.path.join(folder, "scene.yaml")
    text = json.dumps(scene, indent=1)  # JSON is YAML
    cmd = run.coupled_command(args.build, path, fluid, dem)
    if nice:
        cmd = ["nice", "-n", str(nice)] + cmd
    done = os.path.join(folder, "wall_s.txt")
    if args.reuse and os.path.exists(done) and os.path.exists(path) and open(path).read() == text:
        print(f"# {name}: reused (--reuse) from {folder}", flush=True)
        with open(done) as f:
            wall = float(f.read())
    else:
        with open(path, "w") as f:
            f.write(text)
        print(f"# {name}: {' '.join(cmd)}", flush=True)
        wall, _ = run.execute(cmd, path, timeout=args.timeout, log=os.path.join(folder, "run.log"))
        with open(done, "w") as f:
            f.write(f"{wall}\n")
    r = Run(path, args.build)
    return point(r.summary("fluid"), r.summary("dem"), wall)


def point(fs, ds, wall):
    """One run from its two summaries: per-rank counters of both sides and the rank-0 split."""
    def ranks(s):
        pr = s["per_rank"]
        n = len(pr["busy_s_per_step"]["values"])
        return [{k: v["values"][i] for k, v in pr.items()} for i in range(n)]
    fp, dp = fs["per_step_s"], ds["per_step_s"]
    # Summaries without CPU times (older programs) give their wall times instead.
    fc, dc = fs.get("per_step_cpu_s", fp), ds.get("per_step_cpu_s", dp)
    dem_part = [k for k in dp if k not in ("exchange", "idle")][0]
    fl, dm = ranks(fs), ranks(ds)
    # The step on cores of their own: each side's busy and coupler CPU time, the longer side
    # (a run without the coupler's CPU time takes its wall time).
    def own(r, side):
        return (r.get("busy_cpu_s_per_step", r["busy_s_per_step"])
                + r.get("coupler_cpu_s_per_step", side["exchange"]))
    cpu_step = max(max(own(r, fp) for r in fl), max(own(r, dp) for r in dm))
    return {"fluid": fl, "dem": dm, "wall": wall, "has_cpu": "per_step_cpu_s" in fs,
            "steps": fs["steps"]["last"] - fs["steps"]["first"],
            "lattice": fp["lattice"], "porosity": fp["porosity + momentum exchange"],
            "lattice_cpu": fc["lattice"], "porosity_cpu": fc["porosity + momentum exchange"],
            "exchange": fp["exchange"], "exchange_cpu": fc.get("exchange", fp["exchange"]),
            "idle": fp["idle"], "cpu_step": cpu_step,
            "step": sum(fp.values()), "dem_s": dp[dem_part], "dem_cpu": dc[dem_part],
            "dem_exchange": dp["exchange"],
            "imbalance": fs["load_imbalance"]["max_over_mean"],
            "work_imbalance": max_over_mean([r["weighted_work"] for r in ranks(fs)])}


def max_over_mean(v):
    m = sum(v) / len(v)
    return max(v) / m if m > 0 else 1.0


def substeps_of(args, name):
    with open(os.path.join(args.out, name, "run.log")) as f:
        for line in f:
            if "DEM substeps of" in line:
                return int(line.split(" DEM substeps of")[0].split()[-1])
    raise SystemExit(f"scaling: {name}: the DEM substep count is missing from run.log")


# ---- counters table ---------------------------------------------------------------------------
FLUID_COLS = ("busy_cpu_s_per_step", "coupler_cpu_s_per_step", "cells", "porous_row_cells",
              "covered_cells", "band_cells", "body_interior_cells", "bodies_in_table",
              "bodies_touching",
              "halo_bytes_per_step", "halo_messages_per_step", "coupler_bytes_per_step",
              "coupler_messages_per_step", "max_rss_mib")
DEM_COLS = ("busy_cpu_s_per_step", "coupler_cpu_s_per_step", "bodies_owned", "atoms",
            "ghost_atoms", "coupler_bytes_per_step", "coupler_messages_per_step",
            "load_bytes_per_step", "max_rss_mib")


def print_counters(label, p):
    for side, cols in (("fluid", FLUID_COLS), ("dem", DEM_COLS)):
        rows = p[side]
        cells = []
        for c in cols:
            if c not in rows[0]:
                continue  # a summary of an older program
            v = [r[c] for r in rows]
            cells.append(f"{c} {min(v):.6g}..{max(v):.6g}" if len(v) > 1 else f"{c} {v[0]:.6g}")
        print(f"  {label} {side} ({len(rows)} ranks): " + ", ".join(cells))


# ---- fit and check ----------------------------------------------------------------------------
def fit_row(args, name, p):
    return {"f": p["fluid"][0], "d": p["dem"][0], "lattice": p["lattice_cpu"],
            "porosity": p["porosity_cpu"], "exchange": p["exchange_cpu"], "dem": p["dem_cpu"],
            "substeps": substeps_of(args, name)}


def model_path(args):
    """The model file of --fit-repeat K: model.json for the 58^3 blocks, model_rK.json else."""
    k = args.fit_repeat
    return os.path.join(args.out, "model.json" if k == 1 else f"model_r{k}.json")


def fit(args):
    # --fit-repeat K: every fit scene repeated K times along each axis, so that a rank holds a
    # block of (58 K)^3 cells, as the paper's systems do (the per-cell costs grow once the
    # populations leave the caches).
    k = args.fit_repeat
    tag = "" if k == 1 else f"_r{k}"

    def big(s):
        return repeated(s, (k, k, k))

    small = with_steps(base_scene(), args.steps)
    base = big(small)
    # The aligned cubes touch few lattice rows per covered cell, the rotated ones many; the
    # porosity part of a rotated cube costs more per covered cell (1.4-1.7 x; its band update
    # evaluates only 14 % more cells), and the suspensions the model predicts are
    # randomly oriented: the porosity costs come from the rotated scenes (8 bodies 29 cells
    # apart: at 1.3 x the edge two facing corners and their bands stay 4 cells apart).
    plan = [("fit_dense", base, 1), ("fit_dilute", big(thinned(small)), 1),
            ("fit_large", big(thinned(small, 1.6)), 1), ("fit_small", big(thinned(small, 0.7)), 1),
            ("fit_rotated", big(rotated(thinned(small))), 1),
            ("fit_rotated_large", big(rotated(thinned(small, 1.3))), 1),
            ("fit_rotated_small", big(rotated(thinned(small, 0.7))), 1)]
    plan = [(name + tag, scene, nf) for name, scene, nf in plan]
    plan.append(("fit_dilute_2" + tag, big(thinned(small)), 2))
    points = best_of(args, plan)
    rows = [dict(fit_row(args, name, points[name]), rotated="rotated" in name)
            for name, _, nf in plan if nf == 1]
    p2 = points["fit_dilute_2" + tag]
    model = scaling.fit_costs(rows, [(p2["fluid"],
                                      [r["busy_cpu_s_per_step"] for r in p2["fluid"]])])
    # The check: points the fit did not use, at 1 and 2 fluid ranks.
    checks = [("check_weak_1", base, 1), ("check_weak_2", repeated(base, (2, 1, 1)), 2),
              ("check_strong_2", base, 2)]
    points.update(best_of(args, [(name + tag, scene, nf) for name, scene, nf in checks]))
    mem_f = [(dict(r), r["max_rss_mib"] * 2**20) for p in points.values() for r in p["fluid"]]
    mem_d = [(dict(r), len_bodies(args, n), r["max_rss_mib"] * 2**20)
             for n, p in points.items() for r in p["dem"]]
    model.memory = scaling.fit_memory(mem_f, mem_d, GLOBAL_BODY_BYTES)
    dense = points["fit_dense" + tag]["fluid"][0]
    nb = len(base["bodies"])
    per_body = {"covered": dense["covered_cells"] / nb, "band": dense["band_cells"] / nb,
                "interior": dense["body_interior_cells"] / nb}
    dem0 = points["fit_dense" + tag]["dem"][0]
    ghost_reach = scaling.ghost_reach_from(dem0["atoms"], dem0["ghost_atoms"], cells_of(base))
    saved = {"costs": model.costs, "memory": model.memory, "per_body": per_body,
             "ghost_reach_cells": ghost_reach, "substeps": rows[0]["substeps"],
             "measured": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
             "load_average": os.getloadavg()[0], "block_cells": math.prod(cells_of(base))}
    with open(model_path(args), "w") as f:
        json.dump(saved, f, indent=1)
    print(f"# per-unit costs fitted on 1 fluid : 1 DEM rank (halo: 2 : 1), blocks of "
          f"{math.prod(cells_of(base))} cells, load average {os.getloadavg()[0]:.1f}")
    names = {"cell": "plain cell (lattice)", "porous_row": "cell of a porous row, extra (lattice)",
             "covered": "covered cell, extra (lattice)",
             "exchange_step": "coupler exchange, fixed per step", "dem_step": "DEM, fixed per step",
             "porosity_cell": "covered cell (porosity + momentum exchange)",
             "body": "body in a rank's table (porosity + momentum exchange)",
             "halo_byte": "halo byte", "coupler_byte": "coupler byte",
             "atom_substep": "DEM atom or ghost per substep"}
    for k, v in model.costs.items():
        print(f"  {names[k]:<56} {v * 1e9:12.3f} ns")
    for k, v in model.memory.items():
        print(f"  memory {k:<49} {v:12.1f} {'B' if 'base' not in k else 'B (per rank)'}")
    print("# check, ms per coupled step: measured wall (fluid rank 0's parts summed, shared "
          "cores), measured on cores of their own (the longer side's busiest rank: CPU time of "
          "the busy parts and the coupler calls) against the model's max(fluid, DEM); busiest "
          "fluid rank's busy CPU time, measured and predicted")
    print(f"  {'run':<16} {'ranks':>5} {'wall':>9} {'own cores':>9} {'model':>9} {'ratio':>6} | "
          f"{'busy CPU':>9} {'model':>9} {'ratio':>6}")
    for name, p in points.items():
        check_line(model, name, p, substeps_of(args, name))
    return model


def best_of(args, plan):
    """{name: point} of the runs (name, scene, fluid ranks; one DEM rank), each run
    --fit-runs times, interleaved (repetition k in folder name.k), keeping the repetition with
    the least busy CPU time of the busiest fluid rank: on shared cores the one least slowed by
    other processes' use of the caches and the memory bus."""
    best = {}
    for k in range(args.fit_runs):
        for name, scene, nf in plan:
            p = launch(args, name if k == 0 else f"{name}.{k + 1}", scene, nf, 1)
            if name not in best or busy_cpu(p) < busy_cpu(best[name]):
                best[name] = p
    return best


def busy_cpu(p):
    return max(r.get("busy_cpu_s_per_step", r["busy_s_per_step"]) for r in p["fluid"])


def len_bodies(args, name):
    with open(os.path.join(args.out, name, "scene.yaml")) as f:
        return len(json.load(f)["bodies"])


def check_line(model, name, p, substeps):
    pred = model.step(p["fluid"], p["dem"], substeps)[0]
    busy = max(r.get("busy_cpu_s_per_step", r["busy_s_per_step"]) for r in p["fluid"])
    busy_pred = max(model.fluid_busy(r) for r in p["fluid"])
    print(f"  {name:<16} {len(p['fluid'])}:{len(p['dem']):<3} {1e3 * p['step']:9.2f} "
          f"{1e3 * p['cpu_step']:9.2f} {1e3 * pred:9.2f} {pred / p['cpu_step']:6.2f} | "
          f"{1e3 * busy:9.2f} {1e3 * busy_pred:9.2f} {busy_pred / busy:6.2f}", flush=True)


def load_model(args):
    path = model_path(args)
    if not os.path.exists(path):
        raise SystemExit(f"scaling: no model in {path}: run with --fit (and the same "
                         "--fit-repeat) first")
    with open(path) as f:
        saved = json.load(f)
    return scaling.Model(saved["costs"], saved["memory"]), saved


def calibrated(args, model):
    """The model with its fluid per-unit costs scaled to the busiest fluid rank's busy CPU time
    measured in run `args.calibrate` (a folder under <out>; Model.calibrated)."""
    r = Run(os.path.join(args.out, args.calibrate, "scene.yaml"), args.build)
    p = point(r.summary("fluid"), r.summary("dem"), 0.0)
    busy = max(x.get("busy_cpu_s_per_step", x["busy_s_per_step"]) for x in p["fluid"])
    factor, model = model.calibrated(p["fluid"], busy)
    print(f"# fluid per-unit costs scaled by {factor:.3f}, the busiest fluid rank's busy CPU "
          f"time measured in {args.calibrate} over the model's")
    return model


# ---- series -----------------------------------------------------------------------------------
def weak_k(p):
    k = [1, 1, 1]
    axis = 0
    while math.prod(k) < p:
        k[axis] *= 2
        axis = (axis + 1) % 3
    if math.prod(k) != p:
        raise SystemExit(f"scaling: weak series needs powers of two, got {p}")
    return tuple(k)


def series(args, kind, ranks, model):
    path = BASE if kind == "weak" else os.path.join(ROOT, "configs", "bench", args.scene + ".yaml")
    base = with_steps(base_scene(path), args.steps)
    tag = "" if path == BASE else "_" + args.scene
    print(f"# {kind} scaling on {os.path.relpath(path, ROOT)}, {args.steps} "
          f"steps, one DEM rank per {args.dem_per_fluid} fluid ranks, load average "
          f"{os.getloadavg()[0]:.1f}. ms per step: wall (shared cores), on cores of their own "
          "(busiest rank's CPU time in its parts and coupler calls, the longer side) and the "
          "model's; MLUPS and "
          "efficiency on cores of their own (weak t1 / tP, strong t1 / (P tP)); imbalance: max / "
          "mean over the fluid ranks of the busy CPU time and of the weighted work")
    print(f"  {'fluid:dem':>9} {'decomp':>8} {'cells':>10} {'bodies':>6} {'wall':>8} "
          f"{'own':>8} {'model':>8} {'MLUPS':>7} {'eff':>5} {'imb CPU':>8} {'imb work':>8}")
    first = None
    results = []
    for p in ranks:
        scene = repeated(base, weak_k(p)) if kind == "weak" else base
        dem = max(1, p // args.dem_per_fluid)
        for decomp in ("regular", "balanced"):
            name = f"{kind}{tag}_{p}_{decomp}"
            r = launch(args, name, with_steps(scene, args.steps, decomp), p, dem)
            cells = math.prod(cells_of(scene))
            pred = model.step(r["fluid"], r["dem"], substeps_of(args, name))[0] if model else 0
            t = r["cpu_step"]
            if first is None:
                first = t
            eff = first / t if kind == "weak" else first / (p * t)
            imb = max_over_mean([x["busy_cpu_s_per_step"] for x in r["fluid"]])
            print(f"  {p:>5}:{dem:<3} {decomp:>8} {cells:>10} {len(scene['bodies']):>6} "
                  f"{1e3 * r['step']:8.2f} {1e3 * t:8.2f} {1e3 * pred:8.2f} "
                  f"{cells / t / 1e6:7.2f} {eff:5.2f} {imb:8.3f} {r['work_imbalance']:8.3f}",
                  flush=True)
            print_counters(f"{name}:", r)
            results.append((name, r))
    return results


# ---- the paper's systems ----------------------------------------------------------------------
def paper_system(n):
    """Cells per side, bodies, dt and substeps of a paper study's cube run (its --plan figures:
    the box of tools/lbdem/study.py's suspension scene)."""
    from lbdem import study
    st = study.Study(study.load_study(PAPER[n]), None, log=lambda *_: None)
    side = (n * math.pi / 6 * st.d ** 3 / 0.3) ** (1 / 3)
    cells = max(1, round(side / st.dx))
    return st, cells


def memory_points(args):
    """(fluid rank counters, RSS bytes) and (DEM rank counters, bodies, RSS bytes) of every run
    under <out> (the fit's, the series', the paper systems')."""
    import glob
    fluid, dem = [], []
    for path in sorted(glob.glob(os.path.join(args.out, "*", "*_fluid_summary.json"))):
        other = path.replace("_fluid_summary.json", "_dem_summary.json")
        if not os.path.exists(other):
            continue
        with open(path) as f, open(other) as g:
            p = point(json.load(f), json.load(g), 0.0)
        if "cells_with_ghosts" not in p["fluid"][0]:
            continue
        bodies = sum(r["bodies_owned"] for r in p["dem"])
        fluid += [(r, r["max_rss_mib"] * 2**20) for r in p["fluid"]]
        dem += [(r, bodies, r["max_rss_mib"] * 2**20) for r in p["dem"]]
    return fluid, dem


def predict(args, model, saved):
    fluid, dem = memory_points(args)
    model.memory = scaling.fit_memory(fluid, dem, GLOBAL_BODY_BYTES)
    print(f"# memory per rank refitted on the {len(fluid)} fluid and {len(dem)} DEM ranks of the "
          f"runs in {args.out}: fluid {model.memory['fluid_base'] / 2**20:.1f} MiB + "
          f"{model.memory['fluid_cell']:.1f} B per cell (with the ghost layer); DEM "
          f"{model.memory['dem_base'] / 2**20:.1f} MiB + {GLOBAL_BODY_BYTES} B per body (global) + "
          f"{model.memory['dem_atom']:.1f} B per local or ghost atom")

    print("# model predictions for the paper's systems (cube suspension at phi = 0.3, 27-sphere "
          "clumps, double precision); best split of the cores between fluid and DEM ranks; "
          "memory per rank from the fitted per-cell and per-atom sizes")
    print(f"  {'cubes':>7} {'cells':>11} {'cores':>5} {'fluid:dem':>10} {'ms/step':>8} "
          f"{'fluid ms':>8} {'DEM ms':>7} {'h / 0.2 s':>9} {'fluid MiB':>9} {'DEM MiB':>8} "
          f"{'table':>6} {'halo kB':>8}")
    out = []
    for n in (3150, 10648, 103823):
        st, cells = paper_system(n)
        a_cells = st.a / st.dx
        reach = math.sqrt(3) / 2 * a_cells + 2.0  # bounding radius + coupling.margin (2 cells)
        touch = math.sqrt(3) / 2 * a_cells
        steps = round(0.2 / st.dt)
        for cores in CORES:
            best = None
            for dem in sorted({max(1, cores // k) for k in (2, 4, 8, 16, 32)}):
                fl = cores - dem
                c = scaling.uniform_counters(cells, n, fl, dem, saved["per_body"], reach, touch,
                                             saved["ghost_reach_cells"], CLUMP_SPHERES)
                t, f, d = model.step([c["fluid"]], [c["dem"]], saved["substeps"])
                if best is None or t < best[0]:
                    best = (t, f, d, fl, dem, c)
            t, f, d, fl, dem, c = best
            fm = model.fluid_memory(c["fluid"]) / 2**20
            dm = model.dem_memory(c["dem"], n) / 2**20
            print(f"  {n:>7} {cells ** 3:>11} {cores:>5} {fl:>5}:{dem:<4} {1e3 * t:8.2f} "
                  f"{1e3 * f:8.2f} {1e3 * d:7.2f} {t * steps / 3600:9.2f} {fm:9.0f} {dm:8.0f} "
                  f"{c['fluid']['bodies_in_table']:6.0f} "
                  f"{c['fluid']['halo_bytes_per_step'] / 1e3:8.0f}")
            out.append((n, cores, fl, dem, t, fm, dm))
    print("# memory per rank on 64 fluid ranks : 16 DEM ranks (model: fitted per-cell and "
          "per-atom sizes, 160 B per body of global tables on every DEM rank)")
    for n in (3150, 10648, 103823):
        st, cells = paper_system(n)
        a_cells = st.a / st.dx
        c = scaling.uniform_counters(cells, n, 64, 16, saved["per_body"],
                                     math.sqrt(3) / 2 * a_cells + 2.0, math.sqrt(3) / 2 * a_cells,
                                     saved["ghost_reach_cells"], CLUMP_SPHERES)
        print(f"  {n:>7} cubes, {cells}^3 cells: fluid {c['fluid']['cells']:.0f} cells per rank "
              f"(grid {c['fluid_dims']}), {model.fluid_memory(c['fluid']) / 2**20:.0f} MiB; DEM "
              f"{c['dem']['atoms']:.0f} atoms + {c['dem']['ghost_atoms']:.0f} ghosts per rank, "
              f"{model.dem_memory(c['dem'], n) / 2**20:.0f} MiB")
    return out


def paper_run(args, model):
    from lbdem import packing, study
    config = study.load_study(args.paper)
    n = int(config["bodies"])
    # --coarsen K: the fluid at 1/K of the resolution, the bodies and the DEM as they are (the
    # DEM's set-up and memory at full size where the lattice would not fit).
    fluid = config["fluid"]
    fluid["cells_per_diameter"] = float(fluid["cells_per_diameter"]) / args.coarsen
    st = study.Study(config, args.build, out=args.out)
    x, q = io.read_bodies_csv(args.packing)
    base = packing.Packing(len(x), packing.PHI_START, st.d)
    base.x, base.q = x, q
    scene, cells, p = st.suspension_scene("cube", 0.3, base)
    del scene["fluid"]["output"]  # no fields or series: the run measures the step
    scene["time"] = {"end": args.steps * st.dt, "progress_interval": 1.0e9}
    # Niced on shared cores a step of the larger systems takes minutes of wall time: no stall
    # limit of a minute.
    scene["coupling"] = {"output_interval": args.steps * st.dt, "stall_timeout": 3600}
    name = f"paper_{n}_{args.ranks[0]}x{args.ranks[1]}" + (
        f"_coarse{args.coarsen}" if args.coarsen != 1 else "")
    folder = os.path.join(args.out, name)
    os.makedirs(folder, exist_ok=True)
    p.save(os.path.join(folder, "bodies.csv"), packing.PHI_START)
    if args.check_only:
        path = os.path.join(folder, "scene.yaml")
        with open(path, "w") as f:
            json.dump(dict(scene, name=name), f, indent=1)
        for prog in ("fluid_app", "dem_app"):
            exe = os.path.join(args.build, prog, prog)
            t0 = time.monotonic()
            _, text = run.execute(["/usr/bin/time", "-v", exe, "--check", path], path)
            rss = [ln for ln in text.splitlines() if "Maximum resident" in ln]
            print(f"# {name} {prog} --check: {time.monotonic() - t0:.1f} s, {rss[0].strip()}")
        return
    r = launch(args, name, scene, args.ranks[0], args.ranks[1], nice=args.nice)
    sub = substeps_of(args, name)
    print(f"# {name}: {cells[0]}^3 = {math.prod(cells)} cells, {n} cubes, {r['steps']} steps, "
          f"{sub} DEM substeps per step, wall {r['wall']:.0f} s, load average "
          f"{os.getloadavg()[0]:.1f}")
    print(f"  time per step {1e3 * r['step']:.1f} ms wall (lattice {1e3 * r['lattice']:.1f}, "
          f"porosity + momentum exchange {1e3 * r['porosity']:.1f}, exchange "
          f"{1e3 * r['exchange']:.1f}, idle {1e3 * r['idle']:.1f}; DEM {1e3 * r['dem_s']:.1f}), "
          f"{math.prod(cells) / r['step'] / 1e6:.2f} MLUPS")
    if r["has_cpu"]:
        print(f"  CPU of fluid rank 0: lattice {1e3 * r['lattice_cpu']:.1f}, porosity + momentum "
              f"exchange {1e3 * r['porosity_cpu']:.1f}; DEM {1e3 * r['dem_cpu']:.1f}; on cores "
              f"of their own {1e3 * r['cpu_step']:.1f} ms, "
              f"{math.prod(cells) / r['cpu_step'] / 1e6:.2f} MLUPS")
    print_counters(name + ":", r)
    if model:
        check_line(model, name, r, sub)
        f0 = r["fluid"][0]
        print(f"  fluid rank 0, CPU ms per step measured / model: lattice "
              f"{1e3 * r['lattice_cpu']:.1f} / {1e3 * model.lattice(f0):.1f} (without the halo), "
              f"porosity + momentum exchange {1e3 * r['porosity_cpu']:.1f} / "
              f"{1e3 * model.porosity(f0):.1f}")
        for side, rows in (("fluid", r["fluid"]), ("DEM", r["dem"])):
            pred = [model.fluid_memory(x) if side == "fluid" else model.dem_memory(x, n)
                    for x in rows]
            measured = ", ".join(f"{x['max_rss_mib']:.0f}" for x in rows)
            model_mib = ", ".join(f"{x / 2**20:.0f}" for x in pred)
            print(f"  max RSS per {side} rank: measured {measured} MiB, model {model_mib} MiB")


# ---- ctest ------------------------------------------------------------------------------------
def ci(args):
    """Two tiny runs of the 8-cube quick scene (1:1 and 3:2 ranks): every counter present in
    the summaries and the log, and consistent."""
    s = io.read_scene_yaml(os.path.join(ROOT, "configs", "bench", "quick_cubes8_c27.yaml"))
    s["shapes"][0]["clump"]["file"] = os.path.join(SHAPES, "cube_27_surface.clump")
    s["dem"]["output"] = {"directory": "."}
    s = with_steps(s, 4)
    n = cells_of(s)
    bad = []

    def expect(ok, what):
        print(f"  {'ok' if ok else 'FAILED'}: {what}")
        if not ok:
            bad.append(what)

    covered = {}
    for nf, nd, dims in ((1, 1, None), (3, 2, (3, 1, 1))):
        name = f"ci_{nf}x{nd}"
        p = launch(args, name, s, nf, nd)
        with open(os.path.join(args.out, name, "run.log")) as f:
            log = f.read()
        for side, cols in (("fluid", FLUID_COLS), ("dem", DEM_COLS)):
            label = "fluid" if side == "fluid" else "DEM"
            for c in cols:
                expect(all(c in r for r in p[side]) and
                       f"per-rank work ({label}, {len(p[side])} ranks): {c} min" in log,
                       f"{name}: {side} counter {c} in the summary and the log line")
        fl, dm = p["fluid"], p["dem"]
        expect(sum(r["cells"] for r in fl) == math.prod(n),
               f"{name}: per-rank cells sum to the lattice, {math.prod(n)}")
        expect(all(r["covered_cells"] == r["band_cells"] + r["body_interior_cells"] for r in fl),
               f"{name}: covered = band + body interior on every rank")
        expect(all(r["covered_cells"] <= r["porous_row_cells"] <= r["cells"] for r in fl),
               f"{name}: covered <= cells of porous rows <= cells on every rank")
        if dims is None:
            expect(fl[0]["porous_row_cells"] % n[0] == 0,
                   f"{name}: one rank's porous rows are whole rows of {n[0]} cells")
        expect(all(0 < r["bodies_touching"] <= r["bodies_in_table"] for r in fl),
               f"{name}: 0 < bodies touching <= bodies in the table")
        expect(sum(r["bodies_owned"] for r in dm) == len(s["bodies"]),
               f"{name}: DEM ranks own the {len(s['bodies'])} bodies")
        expect(sum(r["atoms"] for r in dm) == CLUMP_SPHERES * len(s["bodies"]),
               f"{name}: DEM atoms = {CLUMP_SPHERES} spheres x bodies")
        for c in ("coupler_bytes_per_step", "coupler_messages_per_step"):
            a, b = sum(r[c] for r in fl), sum(r[c] for r in dm)
            expect(a == b and a > 0, f"{name}: {c} summed over the fluid ranks ({a}) = over the "
                   f"DEM ranks ({b}): every packet one side sends the other receives")
        # The states of step 0 come before the first step and are not counted per step.
        expect(all(r["coupler_bytes_per_step"] == r["bodies_in_table"] * (
            scaling.STATE_BYTES + scaling.LOAD_BYTES) for r in fl),
               f"{name}: fluid coupler bytes = (state + load) x bodies in the table per step")
        expect(all(r["max_rss_mib"] > 0 for r in fl + dm), f"{name}: max RSS on every rank")
        if dims is None:
            expect(fl[0]["halo_bytes_per_step"] == 0, f"{name}: one rank sends no halo")
        else:
            # Every rank a 1-axis slab of the periodic box: the model's halo links, bit for bit.
            for r in fl:
                block = (round(r["cells"] / (n[1] * n[2])), n[1], n[2])
                want = 8 * scaling.halo_values(block, dims)[0]
                expect(r["halo_bytes_per_step"] == want and
                       r["halo_messages_per_step"] == scaling.halo_values(block, dims)[1],
                       f"{name}: halo bytes of a {block} slab = the model's {want}")
        covered[name] = sum(r["covered_cells"] for r in fl)
    a, b = covered.values()
    expect(abs(a - b) <= 0.005 * a, f"covered cells summed over ranks agree, 1:1 {a} and 3:2 {b}")
    if bad:
        raise SystemExit(f"scaling --ci: {len(bad)} check(s) failed")
    print("scaling --ci: all checks passed")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "scaling"))
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--timeout", type=float, default=3600)
    ap.add_argument("--reuse", action="store_true",
                    help="take a run whose folder holds the same scene and a finished run")
    ap.add_argument("--ci", action="store_true")
    ap.add_argument("--fit", action="store_true")
    ap.add_argument("--fit-repeat", type=int, default=1, metavar="K",
                    help="--fit on the fit scenes repeated K times along each axis (blocks of "
                         "(58 K)^3 cells per rank), saved as model_rK.json; with --predict or "
                         "--paper: use that model")
    ap.add_argument("--fit-runs", type=int, default=1, metavar="K",
                    help="--fit: run each fit and check scene K times, interleaved, and keep the "
                         "run with the least busy CPU time (shared cores)")
    ap.add_argument("--weak", type=int, nargs="*")
    ap.add_argument("--strong", type=int, nargs="*")
    ap.add_argument("--dem-per-fluid", type=int, default=4)
    ap.add_argument("--scene", default="cubes64_c27",
                    help="configs/bench scene of the strong series (bed64_c27: a settled bed)")
    ap.add_argument("--predict", action="store_true")
    ap.add_argument("--calibrate", metavar="RUN",
                    help="scale the fluid per-unit costs to the busy CPU time measured in RUN, a "
                         "run folder under --out (e.g. paper_3150_2x1), for --paper and --predict")
    ap.add_argument("--paper", help="a study file (configs/study/paper_*.yaml) to run here")
    ap.add_argument("--packing", help="its phi = 0.4 packing (tools/make_packing.py)")
    ap.add_argument("--ranks", type=int, nargs=2, default=[2, 1], metavar=("FLUID", "DEM"))
    ap.add_argument("--nice", type=int, default=10, help="with --paper: its niceness")
    ap.add_argument("--coarsen", type=int, default=1,
                    help="with --paper: the fluid's dx times this (the DEM at full size)")
    ap.add_argument("--check-only", action="store_true",
                    help="with --paper: both programs' --check of the scene, with max RSS")
    args = ap.parse_args()
    args.build, args.out = os.path.abspath(args.build), os.path.abspath(args.out)
    os.makedirs(args.out, exist_ok=True)
    if args.ci:
        ci(args)
        return
    model, saved = (fit(args), None) if args.fit else (None, None)
    if model is not None or args.predict or args.weak or args.strong or args.paper:
        if os.path.exists(model_path(args)):
            model, saved = load_model(args)
    if args.calibrate:
        if model is None:
            model, saved = load_model(args)
        model = calibrated(args, model)
    if args.weak:
        series(args, "weak", args.weak, model)
    if args.strong:
        series(args, "strong", args.strong, model)
    if args.paper:
        paper_run(args, model)
    if args.predict:
        if saved is None:
            model, saved = load_model(args)
        predict(args, model, saved)


if __name__ == "__main__":
    main()
