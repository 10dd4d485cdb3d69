"""The hindered-settling study (docs/study.md): for a list of solid fractions and shapes, one
packing, one single-body run per shape (its terminal velocity u_T at the same resolution and tau),
one triply periodic run per (shape, phi), the analysis of each and the summary table and plots.

Resumable: a run whose folder holds result.json for the same scene and the same build (a digest
of the two programs) is skipped; a folder without it (an interrupted run) is emptied and the run
starts again from t = 0.
"""
import json
import math
import os
import shutil
import time

import numpy as np
import yaml

from . import analysis, io, packing, references, run

RUN_FILES = ("scene.yaml", "bodies.csv")
# Largest change of fluid + bodies - applied impulse, relative to the bodies' largest momentum,
# that the study accepts: the audit holds it to ~1e-12 in double and ~3e-5 in float precision
# (docs/method-loads.md section 7, docs/precision.md); a lost force shows at the per cent level.
MOMENTUM_TOLERANCE = 1e-3
# Radius, in d, below which the mean of g(r) tracks the near structure (analysis.near_pair_series):
# the first shell of g(r), which at phi 0.1-0.3 lies between d and about 1.4 d.
NEAR_PAIRS = 1.5
# The fluid's number type (the scene's fluid.precision): float halves the populations' memory
# traffic; what it changes in the validation cases and the study is in docs/precision.md.
PRECISIONS = ("double", "float")


def momentum_change(audit_path):
    """Largest change of the momentum of fluid plus bodies, less the applied impulse, over a
    run's momentum audit (<name>_momentum.csv), relative to the largest body momentum. From the
    first coupled step on: the DEM's set-up reports the starting velocity with half a substep of
    gravity but not of the buoyancy (tools/validate_case.py momentum)."""
    audit = io.read_series(audit_path)
    after = audit["step"] >= 1

    def columns(kind):
        return np.stack([audit[f"{kind}_p{a}"][after] for a in "xyz"], axis=-1)

    bodies = columns("bodies")
    change = analysis.momentum_change(columns("fluid"), bodies, columns("applied"))
    return float(np.abs(change).max() / np.abs(bodies).max())


def momentum_warning(name, row):
    """The warning line of a run whose fluid + bodies did not hold their momentum, else None."""
    if row["momentum_change"] <= MOMENTUM_TOLERANCE:
        return None
    return (f"study: {name}: WARNING the momentum of fluid + bodies changed by "
            f"{row['momentum_change']:.3g} of the bodies' momentum beyond the applied impulse "
            f"(accepted: {MOMENTUM_TOLERANCE:g}): a force is lost between fluid and bodies")


def load_study(path):
    with open(path) as f:
        s = yaml.safe_load(f)
    s["_file"] = os.path.abspath(path)
    return s


def merged(base, extra):
    """Deep merge of mappings (extra wins)."""
    out = dict(base)
    for k, v in (extra or {}).items():
        out[k] = merged(out[k], v) if isinstance(v, dict) and isinstance(out.get(k), dict) else v
    return out


class Study:
    def __init__(self, config, build, out=None, log=print):
        self.c, self.build, self.log = config, build, log
        base = os.path.dirname(config["_file"])
        self.out = os.path.abspath(out or os.path.join(base, config.get("output", ".")))
        p, f = config["particle"], config["fluid"]
        self.d, self.rho_p = float(p["diameter"]), float(p["density"])
        self.a = packing.CUBE_PER_SPHERE * self.d
        self.nu, self.rho_f = float(f["viscosity"]), float(f.get("density", 1000.0))
        self.tau = float(f["tau"])
        self.precision = f.get("precision")
        if self.precision not in (None, *PRECISIONS):
            raise ValueError(f"{config['_file']}: fluid.precision: expected one of "
                             f"{', '.join(PRECISIONS)}, got {self.precision!r}")
        self.dx = self.d / float(f["cells_per_diameter"])
        # Lattice viscosity (tau - 1/2) / 3 in units dx^2 / dt.
        self.dt = (self.tau - 0.5) / 3.0 * self.dx**2 / self.nu
        self.clump = os.path.normpath(os.path.join(base, config["cube_clump"]))
        self.finished = []  # (steps, cells, bodies, wall s) of the runs of this call
        self.relaxed_packings = {}  # phi -> packing relaxed there (self.relaxed)
        self.lattice_rate, self.body_cost = 9.0e6, 2.2e-4  # measured here (docs/study.md, "Cost")
        self.ranks = int(config.get("run", {}).get("ranks", [1, 1])[0])

    def estimate(self, steps, cells, bodies):
        """Wall seconds of a run: steps x (cells / rate + bodies x per-body cost) / fluid ranks,
        the lattice and the porosity + momentum exchange of a coupled step (docs/study.md,
        "Cost"). Before any run: 9e6 cell updates/s per rank and 0.22 ms per body and step at 6
        cells per diameter, times (cells per d / 6)^2 (the band's cells); after runs, both fitted
        to them by least squares (only the rate while all finished runs have one body count)."""
        per_body = self.body_cost * (self.d / self.dx / 6.0) ** 2
        inv_rate = 1.0 / self.lattice_rate
        if self.finished:
            a = np.array([[n * c, n * b] for n, c, b, _ in self.finished], float)
            w = np.array([t for *_, t in self.finished], float) * self.ranks
            if len({b for *_, b, _ in self.finished}) > 1:
                fit = np.linalg.lstsq(a, w, rcond=None)[0]
                if np.all(fit > 0):
                    inv_rate, per_body = fit
            else:
                inv_rate = max((w - a[:, 1] * per_body).sum() / a[:, 0].sum(), 1e-12)
        return steps * (cells * inv_rate + bodies * per_body) / self.ranks

    # ---- scenes -------------------------------------------------------------------------------
    def shape_entry(self, shape):
        if shape == "sphere":
            return {"name": "sphere", "kind": "sphere", "diameter": self.d}
        return {"name": "cube", "kind": "cube", "edge": self.a,
                "clump": {"file": self.clump, "scale": self.a}}

    def base_scene(self, name, domain, end):
        r = self.c["run"]
        scene = {
            "name": name,
            "time": {"end": end, "progress_interval": 30},
            "fluid": {"domain": domain, "dx": self.dx, "viscosity": self.nu, "density": self.rho_f,
                      "tau": self.tau, "characteristic_velocity": 0.05,
                      "characteristic_length": self.d,
                      "output": {"directory": ".", "series": {"interval": r["output_interval"]},
                                 "fields": {"interval": end, "velocity": True}}},
            "dem": {"gravity": [0, 0, -9.81], "dt_fraction": 0.05,
                    "material": {"young_modulus": 5.0e4, "poisson_ratio": 0.3, "restitution": 0.9,
                                 "friction": 0.6},
                    "output": {"directory": "."}},
            "coupling": {"output_interval": r["output_interval"]},
        }
        if self.precision:  # only when chosen, so that existing studies' scenes stay as they were
            scene["fluid"]["precision"] = self.precision
        return merged(scene, self.c.get("scene_overrides"))

    def single_scene(self, shape):
        sc = self.c["single"]
        cells = [int(round(k * self.d / self.dx)) for k in sc["box"]]
        domain = [n * self.dx for n in cells]
        s = self.base_scene(f"single_{shape}", domain, float(sc["end"]))
        # The validation case's boundaries (sphere_terminal_d12_tau055.yaml): pressure (0 Pa) on
        # the side faces, walls at the ends. With periodic sides the body's images 5 d apart
        # would slow it by about 5 % (docs/validation.md, "Side boundaries"), raising every
        # u/u_T by as much.
        s["fluid"]["boundaries"] = {"x_min": "pressure", "x_max": "pressure", "y_min": "pressure",
                                    "y_max": "pressure", "z_min": "wall", "z_max": "wall"}
        s["dem"].update({"periodic": "", "walls": [{"axis": "z", "side": "lo"},
                                                   {"axis": "z", "side": "hi"}]})
        s["shapes"] = [self.shape_entry(shape)]
        z = domain[2] - float(sc["release_below_top"]) * self.d
        s["bodies"] = [{"shape": shape, "position": [domain[0] / 2, domain[1] / 2, z],
                        "density": self.rho_p}]
        return s, cells

    def suspension_scene(self, shape, phi, base_packing):
        # The box is a whole number of cells at the study's dx: the phi = 0.4 packing is scaled to
        # the box of round(L / dx) cells (one more if that would compress it beyond 0.4), so the
        # measured phi is within about 1.5 / (L / dx) x 3 of the nominal one.
        n = max(1, round(base_packing.scaled(phi).box / self.dx))
        while n * self.dx < base_packing.box:
            n += 1
        box = n * self.dx
        p = self.relaxed(base_packing, base_packing.n * math.pi / 6 * self.d**3 / box**3)
        s = self.base_scene(f"{shape}_phi{phi:.3f}", [box] * 3, float(self.c["run"]["end"]))
        s["dem"]["periodic"] = "xyz"
        s["shapes"] = [self.shape_entry(shape)]
        s["bodies"] = [{"file": "bodies.csv", "shape": shape, "density": self.rho_p}]
        return s, [n] * 3, p

    def relaxed(self, base_packing, phi):
        """The packing scaled to phi and relaxed there (packing.relax, `packing.relax_sweeps`
        sweeps, default 1000; 0 keeps the scaled packing); made once per phi and call."""
        key = round(phi, 12)
        if key not in self.relaxed_packings:
            p = base_packing.scaled(phi)
            sweeps = int(self.c["packing"].get("relax_sweeps", 1000))
            if sweeps > 0:
                packing.relax(p, sweeps, int(self.c["packing"]["seed"]),
                              packing.relax_step(phi), log=self.log)
                spheres, cubes = p.overlaps()
                if spheres or cubes:
                    raise RuntimeError(f"packing at phi {phi:.4g}: {spheres} sphere and {cubes} "
                                       "cube overlaps after relaxing")
            p.relax_sweeps = sweeps
            self.relaxed_packings[key] = p
        return self.relaxed_packings[key]

    # ---- runs ---------------------------------------------------------------------------------
    def packing(self):
        cfg = self.c["packing"]
        path = os.path.join(self.out, "packing_phi0.40.csv")
        n = int(self.c["bodies"])
        if os.path.exists(path):
            x, q = io.read_bodies_csv(path)
            if len(x) == n:
                p = packing.Packing(n, packing.PHI_START, self.d)
                p.x, p.q = x, q
                self.log(f"study: packing of {n} bodies reused from {path}")
                return p
        t0 = time.monotonic()
        p = packing.make_packing(n, int(cfg["sweeps"]), int(cfg["seed"]), self.d, self.log)
        spheres, cubes = p.overlaps()
        if spheres or cubes:
            raise RuntimeError(f"packing: {spheres} sphere and {cubes} cube overlaps")
        os.makedirs(self.out, exist_ok=True)
        p.save(path, packing.PHI_START)
        self.log(f"study: packing of {n} bodies at phi 0.4 in {time.monotonic() - t0:.0f} s, "
                 f"lattice order {p.order_parameter():.3f} (random: ~{1 / math.sqrt(n):.2f}), "
                 f"no overlaps; {path}")
        return p

    def launch(self, name, scene, cells, bodies=None, index=0, total=1, remaining=0.0):
        """Runs one scene in <out>/<name>/ unless its result is there; returns the result dict."""
        folder = os.path.join(self.out, name)
        text = yaml.safe_dump(scene, sort_keys=False)
        result_file = os.path.join(folder, "result.json")
        build = run.build_id(self.build)
        if os.path.exists(result_file):
            with open(os.path.join(folder, "scene.yaml")) as f, open(result_file) as g:
                same_scene, res = f.read() == text, json.load(g)
            if same_scene and res.get("build") == build:
                self.log(f"study: [{index}/{total}] {name}: done earlier "
                         f"({res['wall_s']:.0f} s), skipped")
                return res
            why = ("the scene changed" if not same_scene else
                   f"the programs changed (build {res.get('build', 'unrecorded')}, now {build})")
            self.log(f"study: [{index}/{total}] {name}: {why}, running it again")
        elif os.path.isdir(folder):
            self.log(f"study: [{index}/{total}] {name}: unfinished earlier, restarting from t = 0")
        if os.path.isdir(folder):
            shutil.rmtree(folder)
        os.makedirs(folder)
        if bodies is not None:
            bodies.save(os.path.join(folder, "bodies.csv"), packing.PHI_START,
                        relaxed=getattr(bodies, "relax_sweeps", None))
        path = os.path.join(folder, "scene.yaml")
        with open(path, "w") as f:
            f.write(text)
        steps = round(scene["time"]["end"] / self.dt)
        work = float(np.prod(cells)) * steps
        n_bodies = 1 if bodies is None else bodies.n
        est = self.estimate(steps, float(np.prod(cells)), n_bodies)
        ranks = self.c["run"].get("ranks", [1, 1])
        self.log(f"study: [{index}/{total}] {name}: {cells[0]}x{cells[1]}x{cells[2]} cells, "
                 f"{steps} steps; estimated {est:.0f} s for this run, {est + remaining:.0f} s to "
                 f"the end of the study; {' '.join(run.coupled_command(self.build, path, *ranks))}")
        wall, _ = run.run(self.build, path, ranks[0], ranks[1], timeout=None,
                          log=os.path.join(folder, "run.log"))
        res = {"name": name, "wall_s": wall, "cells": cells, "steps": steps,
               "cell_updates_per_s": work / wall, "ranks": ranks, "build": build}
        self.finished.append((steps, float(np.prod(cells)), n_bodies, wall))
        with open(result_file, "w") as f:
            json.dump(res, f, indent=1)
        self.log(f"study: [{index}/{total}] {name}: finished in {wall:.0f} s "
                 f"({work / wall / 1e6:.2f} M cell updates/s)")
        return res

    def terminal_velocity(self, shape, result):
        scene = os.path.join(self.out, result["name"], "scene.yaml")
        tr = io.Trace(io.trace_path(scene))
        speed = -tr["vz"][:, 0]
        tail = speed[tr.time >= 0.8 * tr.time[-1]]
        return float(tail.mean()), float((tail[-1] - tail[0]) / tail.mean())

    def analyse(self, shape, phi, result, u_t):
        scene_path = os.path.join(self.out, result["name"], "scene.yaml")
        scene = io.load_scene(scene_path)
        box = np.array(scene["fluid"]["domain"], float)
        tr = io.Trace(io.trace_path(scene_path, scene))
        series = io.read_series(io.series_path(scene_path, scene))
        n = len(tr.id)
        phi_m = n * math.pi / 6 * self.d**3 / np.prod(box)
        j = np.interp(tr.time, series["time_s"], series["mean_uz_m_s"])
        speed = -analysis.settling_velocity(tr["vz"].mean(axis=1), j)
        # Steady once both the settling speed and the near structure (the mean of g(r) below
        # NEAR_PAIRS d, analysis.near_pair_series) have stopped drifting: MSER on each, the later.
        near = analysis.near_pair_series(tr.vectors(""), box,
                                         min(NEAR_PAIRS * self.d, 0.5 * box.min()))
        start_speed, start_structure = analysis.mser_start(speed), analysis.mser_start(near)
        start = max(start_speed, start_structure)
        mean, err = analysis.block_average(speed[start:])
        # The settling balance holds the momentum of fluid + bodies, not the volume flux j (with
        # rho_p != rho_f, j = phi <u_p> (1 - rho_p / rho_f) in the zero-momentum frame); j is the
        # frame u/u_T is measured in, and its drift is reported.
        j_slope = float(np.polyfit(tr.time[start:], j[start:], 1)[0]) if len(j) - start > 1 else 0.0
        steady = slice(max(start, len(tr.time) - 100), None)  # the paper: the last 100 snapshots
        x, v = tr.vectors("")[steady], tr.vectors("v")[steady]
        r, g = analysis.radial_distribution(x, box, bins=int(self.c.get("rdf_bins", 40)))
        rc, c = analysis.velocity_correlation(x, v[..., 2], box,
                                              bins=int(self.c.get("correlation_bins", 10)))
        vacf = analysis.vacf(v[..., :2])
        dt_out = float(np.median(np.diff(tr.time)))
        out = {"shape": shape, "phi_nominal": phi, "phi": phi_m, "bodies": n,
               "box_cells": result["cells"][0], "cells_per_diameter": self.d / self.dx,
               "tau": self.tau, "u_T": u_t, "settling_velocity": mean, "error": err,
               "u_over_uT": mean / u_t, "u_over_uT_error": err / u_t,
               "richardson_zaki": references.richardson_zaki(phi_m, self.c["reynolds"]),
               "yin_koch": references.yin_koch(phi_m, self.c["reynolds"]),
               # Batchelor's dilute limit only where it is meant to hold.
               "batchelor": references.batchelor(phi_m) if phi_m <= 0.1 else None,
               "t_steady": float(tr.time[start]),
               "t_end": float(tr.time[-1]),
               # The same times in d / u_T, the single body's time to fall its own diameter.
               "t_steady_speed_d_uT": float(tr.time[start_speed] * u_t / self.d),
               "t_steady_structure_d_uT": float(tr.time[start_structure] * u_t / self.d),
               "t_end_d_uT": float(tr.time[-1] * u_t / self.d),
               "near_pairs_start": float(near[:5].mean()),
               "near_pairs_steady": float(near[start:].mean()),
               "volume_flux_end": float(j[-1]),
               "volume_flux_drift": j_slope,
               "momentum_change": momentum_change(io.momentum_path(scene_path, scene)),
               "snapshots_analysed": int(len(x)),
               "wall_s": result["wall_s"]}
        curves = {"time": tr.time, "speed": speed, "near": near, "r": r, "g": g, "rc": rc, "C": c,
                  "lag": dt_out * np.arange(len(vacf)), "vacf": vacf}
        if shape == "cube":
            q = tr.quaternions()[steady]
            cos = analysis.axes_against_gravity(q)
            angles = analysis.contact_face_angles(x, q, box, self.a, 0.05 * self.a)
            out["mean_abs_cos_axis_gravity"] = float(cos.mean())
            out["max_abs_cos_axis_gravity"] = float(cos.max(axis=-1).mean())
            out["touching_pairs"] = int(len(angles))
            out["face_parallel_fraction"] = (float(np.mean(angles < 5.0)) if len(angles)
                                             else float("nan"))
            curves["cos"], curves["face_angles"] = cos.ravel(), angles
        np.savez(os.path.join(self.out, result["name"], "analysis.npz"), **curves)
        with open(os.path.join(self.out, result["name"], "analysis.json"), "w") as f:
            json.dump(out, f, indent=1)
        return out, curves

    def execute(self, shapes=None, phis=None, render=True):
        shapes = shapes or self.c["shapes"]
        phis = phis or [float(v) for v in self.c["solid_fractions"]]
        os.makedirs(self.out, exist_ok=True)
        base = self.packing()
        jobs = [("single", s, None) for s in shapes] + [("suspension", s, phi) for s in shapes
                                                        for phi in phis]
        scenes = []
        for kind, shape, phi in jobs:
            if kind == "single":
                sc, cells = self.single_scene(shape)
                scenes.append((f"single_{shape}", sc, cells, None))
            else:
                sc, cells, p = self.suspension_scene(shape, phi, base)
                scenes.append((sc["name"], sc, cells, p))
        results = {}
        for k, (name, sc, cells, p) in enumerate(scenes):
            remaining = sum(self.estimate(round(s["time"]["end"] / self.dt), float(np.prod(c)),
                                          1 if q is None else q.n)
                            for _, s, c, q in scenes[k + 1:])
            results[name] = self.launch(name, sc, cells, p, k + 1, len(scenes), remaining)
        rows, curves = [], {}
        for shape in shapes:
            u_t, drift = self.terminal_velocity(shape, results[f"single_{shape}"])
            self.log(f"study: single {shape}: u_T = {u_t:.5g} m/s (change over the last 20 % of "
                     f"the run {100 * drift:+.2f} %)")
            for phi in phis:
                name = f"{shape}_phi{phi:.3f}"
                row, cv = self.analyse(shape, phi, results[name], u_t)
                rows.append(row)
                curves[(shape, phi)] = cv
                batchelor = ("" if row["batchelor"] is None
                             else f", Batchelor {row['batchelor']:.4f}")
                self.log(f"study: {name}: phi {row['phi']:.4f}, u/u_T = {row['u_over_uT']:.4f} +- "
                         f"{row['u_over_uT_error']:.4f} (Richardson-Zaki "
                         f"{row['richardson_zaki']:.4f}{batchelor}), steady from "
                         f"{row['t_steady']:.3g} s; in the frame of the volume flux j = "
                         f"{row['volume_flux_end']:.4g} m/s (at the end); momentum of fluid + "
                         f"bodies held to {row['momentum_change']:.2g} of the bodies'")
                warning = momentum_warning(name, row)
                if warning:
                    self.log(warning)
                if render:
                    self.render(name)
        self.write_summary(rows)
        fits = self.fit_hindered_settling(rows)
        from . import plots
        for png in plots.study_plots(rows, curves, self.out, self.c["reynolds"], self.d, self.a,
                                     fits, NEAR_PAIRS):
            self.log(f"study: plot {png}")
        return rows

    def fit_hindered_settling(self, rows):
        """Per shape, u/u_T = k (1 - phi)^n fitted to the runs (at least two solid fractions),
        against Yin & Koch's fit at the study's Reynolds number; written to fits.csv."""
        re = self.c["reynolds"]
        k_yk, n_yk = references.yin_koch_fit(re)
        fits = {}
        for shape in dict.fromkeys(r["shape"] for r in rows):
            sel = [r for r in rows if r["shape"] == shape]
            if len(sel) < 2:
                continue
            f = analysis.fit_hindered_settling([r["phi"] for r in sel],
                                               [r["u_over_uT"] for r in sel],
                                               [r["u_over_uT_error"] for r in sel])
            f.update(shape=shape, points=len(sel), reynolds=re, yin_koch_k=k_yk, yin_koch_n=n_yk)
            fits[shape] = f
            self.log(f"study: {shape}s: u/u_T = k (1 - phi)^n fitted to {len(sel)} runs: "
                     f"k = {f['k']:.3f} +- {f['k_error']:.3f}, n = {f['n']:.2f} +- "
                     f"{f['n_error']:.2f} (rms residual {100 * f['rms_relative_residual']:.1f} %); "
                     f"Yin & Koch at Re {re:g}: k = {k_yk:.2f}, n = {n_yk:.2f}")
        if fits:
            path = os.path.join(self.out, "fits.csv")
            keys = ["shape", "points", "reynolds", "k", "k_error", "n", "n_error",
                    "rms_relative_residual", "yin_koch_k", "yin_koch_n"]
            with open(path, "w") as f:
                f.write(",".join(keys) + "\n")
                for fit in fits.values():
                    f.write(",".join(str(fit[k]) for k in keys) + "\n")
            self.log(f"study: fits {path}")
        return fits

    def write_summary(self, rows):
        path = os.path.join(self.out, "summary.csv")
        keys = list(dict.fromkeys(k for r in rows for k in r))
        with open(path, "w") as f:
            f.write(",".join(keys) + "\n")
            for r in rows:
                f.write(",".join("" if r.get(k) is None else str(r.get(k)) for k in keys) + "\n")
        self.log(f"study: summary {path}")

    def render(self, name):
        from . import picture
        scene = os.path.join(self.out, name, "scene.yaml")
        try:
            png = picture.render_png(scene, self.log)
        except (RuntimeError, FileNotFoundError) as e:  # a picture is not worth the study
            self.log(f"study: {name}: no picture, the render failed: {str(e)[-600:]}")
            png = None
        self.log(f"study: {name}: body surfaces {picture.surfaces_path(scene)}" +
                 (f", picture {png}" if png else ""))
