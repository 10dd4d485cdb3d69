#!/usr/bin/env python3
"""Validation of the sub-grid lubrication correction in coupled runs (docs/lubrication.md).

    validate_lubrication.py approach --build build --scene S [--ranks 1:1] [--tolerance T]
    validate_lubrication.py bounce --build build --scene S [S ...] [--without] [--tolerance T]
                                   [--min-gap-ratio R]

approach: one sphere driven towards the lower wall (one body) or two equal spheres driven
towards each other along z (two bodies), at constant speed. Reads the body trace, and for each
recorded gap h compares the lattice's normal force (lambda = F / (6 pi mu a U)) and the lattice
force plus the correction with Brenner's (1961) exact series. Prints a table over h / a, the
largest relative error of both over max(a/20, dx/4) <= h <= a, also for other cut-offs h_c, appends a
row to runs/validation/results.csv and exits 1 when the corrected error exceeds the tolerance.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "analysis"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lubrication_reference as ref  # noqa: E402
import validate_case  # noqa: E402
import yaml  # noqa: E402
from lbdem import io, run  # noqa: E402
from lbdem import scene as lbdem_scene  # noqa: E402


def approach_samples(build, scene, bodies):
    """[(h, lambda_lattice)] from the trace; U, a, wall."""
    resolved = lbdem_scene.resolve(build, scene)
    s, lattice = resolved["scene"], resolved["derived"]["fluid"]
    a = 0.5 * s["shapes"][0]["diameter"]
    f = s["fluid"]
    mu = f["density"] * f["viscosity"]
    dt = lattice["dt"]
    wall = len(bodies) == 1
    u = abs(resolved["bodies"][0]["velocity"][2])
    out = []
    rows = zip(*[bodies[i] for i in sorted(bodies)])
    for r in rows:
        if r[0]["time"] == 0:
            continue
        # The load of a row was computed by the fluid from the state one step earlier.
        if wall:
            h = r[0]["z"] + u * dt - a
            force = r[0]["fz"]
        else:
            h = r[1]["z"] - r[0]["z"] - 2 * a - 2 * u * dt
            force = 0.5 * (r[1]["fz"] - r[0]["fz"])
        out.append((h, force / (6 * math.pi * mu * a * u)))
    return out, a, wall, lattice["dx"]


def cmd_approach(args):
    wall_s = 0.0
    if not args.no_run:
        wall_s, _ = run.run(args.build, args.scene, *map(int, args.ranks.split(":")))
    trace = io.trace_path(args.scene)
    samples, a, wall, dx = approach_samples(args.build, args.scene, io.read_trace_by_body(trace))
    s = io.load_scene(args.scene)
    lub = s["dem"]["lubrication"]
    h_min = lub["min_gap"]
    h_c = lub.get("cutoff") or lub.get("cutoff_cells", 1.0) * dx
    brenner = ref.brenner_wall if wall else ref.brenner_pair
    name = validate_case.case_name(args)

    def at(h_over_a):
        return min(samples, key=lambda x: abs(x[0] / a - h_over_a))

    print(f"{name}: {'sphere-wall' if wall else 'sphere-sphere'}, d/dx = {2 * a / dx:.3g}, "
          f"h_c = {h_c / dx:.3g} cells, h_min = {h_min / a:.3g} a")
    print(f"{'h/a':>7} {'h/dx':>7} {'Brenner':>9} {'lattice/B':>10} {'+corr/B':>9}")
    for target in (2.0, 1.0, 0.5, 0.25, 0.125, 0.0625):
        h, lam = at(target)
        if abs(h / a - target) > 0.1 * target:
            continue
        b = brenner(h, a)
        c = ref.correction(h, a, h_c, h_min, wall)
        print(f"{h / a:7.4f} {h / dx:7.3f} {b:9.4g} {lam / b:10.4f} {(lam + c) / b:9.4f}")

    # Below about a quarter cell the sphere's smoothed band reaches the wall's (or the other
    # sphere's) first nodes and the lattice force is no longer a squeeze force (it reverses);
    # the comparison stops there.
    reversed_at = [h for h, lam in samples if lam < 0]
    if reversed_at:
        print(f"the lattice force reverses below h = {max(reversed_at) / dx:.3g} cells "
              f"({max(reversed_at) / a:.3g} a)")
    lowest = max(a / 20, dx / 4)
    window = [(h, lam) for h, lam in samples if lowest <= h <= a]

    def worst(cutoff):
        return max(abs((lam + (ref.correction(h, a, cutoff, h_min, wall) if cutoff else 0)) /
                       brenner(h, a) - 1) for h, lam in window)

    without = worst(0)
    print(f"largest |F/F_Brenner - 1| over {lowest / a:.3g} a <= h <= a: lattice alone "
          f"{100 * without:.1f} %")
    for cells in (0.5, 0.75, 1.0, 1.25, 1.5, 2.0):
        print(f"  with the correction, h_c = {cells:.3g} cells: {100 * worst(cells * dx):.1f} %")
    error = worst(h_c)
    ranks = args.ranks.replace(":", "/")
    validate_case.append_row(name, f"{2 * a / dx:.3g}", s["fluid"]["tau"],
                             "max |F/F_Brenner-1| lattice only", 0, f"{without:.4g}",
                             f"{without:.4g}", wall_s, ranks)
    validate_case.append_row(name, f"{2 * a / dx:.3g}", s["fluid"]["tau"],
                             "max |F/F_Brenner-1| with correction", 0, f"{error:.4g}",
                             f"{error:.4g}", wall_s, ranks)
    print(f"{name}: with the correction (h_c = {h_c / dx:.3g} cells) the largest error is "
          f"{100 * error:.2f} %, lattice alone {100 * without:.2f} %; wall time {wall_s:.1f} s")
    print(f"[validation] {name}: largest |F / F_Brenner - 1| with the correction error "
          f"{error:.4g}, tolerance {args.tolerance:g} (run time {wall_s:.1f} s)")
    if error > args.tolerance:
        print(f"FAILED: error {100 * error:.2f} % above the tolerance {100 * args.tolerance:.2f} %")
        return 1
    return 0


def scene_variant(scene, suffix, edit):
    """A copy of the scene named <name>_<suffix>, changed by edit(yaml dict), in
    runs/lubrication/<name>_<suffix>; returns its path."""
    s = io.read_scene_yaml(scene)  # written back as a variant; values come from the JSON
    s["name"] = s["name"] + "_" + suffix
    edit(s)
    directory = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "runs",
                             "lubrication", s["name"])
    os.makedirs(directory, exist_ok=True)
    s["dem"]["output"]["directory"] = "."
    path = os.path.join(directory, s["name"] + ".yaml")
    with open(path, "w") as f:
        yaml.safe_dump(s, f)
    return path


def scene_without_correction(scene):
    """A copy of the scene with dem.lubrication.enabled false, in runs/lubrication/<name>_off."""
    return scene_variant(scene, "off", lambda s: s["dem"]["lubrication"].update(enabled=False))


def scene_with_min_gap_ratio(scene, ratio):
    """A copy of the scene with h_min = ratio x the sphere's radius (the roughness relative to
    the radius, docs/lubrication.md "Minimum gap"), in runs/lubrication/<name>_hmin<ratio>."""
    a = 0.5 * io.load_scene(scene)["shapes"][0]["diameter"]
    return scene_variant(scene, f"hmin{ratio:g}",
                         lambda s: s["dem"]["lubrication"].update(min_gap=float(ratio * a)))


def restitution(scene, rows):
    """(U_in, U_contact, U_film, St) of the first bounce. U_in: the largest downward speed before
    the first reversal. U_contact: the upward speed at the first output after the reversal (it
    may fall inside the sub-cell film, before the film's suction has acted, so it depends on
    where the output falls). U_film: the upward speed when the gap has grown back to h_c, where
    the correction stops acting and the lattice resolves the flow again (linear interpolation
    between outputs; 0 when the sphere never gets there: captured by the film)."""
    s = io.load_scene(scene)
    f = s["fluid"]
    d = s["shapes"][0]["diameter"]
    a = 0.5 * d
    rho_p = s["bodies"][0]["density"]
    lub = s["dem"]["lubrication"]
    h_c = lub.get("cutoff") or lub.get("cutoff_cells", 1.0) * f["dx"]
    turn = next((i for i in range(1, len(rows)) if rows[i - 1]["vz"] < 0 <= rows[i]["vz"]), None)
    u_in = max(-r["vz"] for r in rows[:turn])
    st = rho_p * u_in * d / (9 * f["density"] * f["viscosity"])
    if turn is None:  # no reversal: the film stopped the sphere (or the run is too short)
        return u_in, 0.0, 0.0, st
    u_contact = max(0.0, rows[turn]["vz"])
    u_film = 0.0
    for r0, r1 in zip(rows[turn:], rows[turn + 1:]):
        if r1["vz"] <= 0:
            break
        h0, h1 = r0["z"] - a, r1["z"] - a
        if h0 < h_c <= h1:
            u_film = r0["vz"] + (r1["vz"] - r0["vz"]) * (h_c - h0) / (h1 - h0)
            break
    return u_in, u_contact, u_film, st


def correction_impulse(scene):
    """Speed the correction alone takes from the sphere in one pass through the film, h_c down
    to h_min (or back): m dU = 6 pi mu a [lambda(h) - lambda(h_c)] dh, integrated (midpoint rule,
    logarithmic in h). Independent of the speed: the film force is linear in it."""
    s = io.load_scene(scene)
    f = s["fluid"]
    a = 0.5 * s["shapes"][0]["diameter"]
    lub = s["dem"]["lubrication"]
    h_c = lub.get("cutoff") or lub.get("cutoff_cells", 1.0) * f["dx"]
    h_min = lub["min_gap"]
    mu = lub.get("viscosity") or f["density"] * f["viscosity"]
    m = s["bodies"][0]["density"] * 4 / 3 * math.pi * a ** 3
    n, total = 2000, 0.0
    for k in range(n):
        lo = h_min * (h_c / h_min) ** (k / n)
        hi = h_min * (h_c / h_min) ** ((k + 1) / n)
        total += ref.correction(math.sqrt(lo * hi), a, h_c, h_min, True) * (hi - lo)
    return 6 * math.pi * mu * a * total / m


def cmd_bounce(args):
    """e = U_film / U_in (after the film, sampling-independent) is the checked number; the
    first output after contact and the correction's own share are printed next to it."""
    failed = 0
    print(f"{'case':>22} {'St':>7} {'U_in m/s':>9} {'e/e_dry':>8} {'contact':>8} "
          f"{'corr.only':>9} {'Legendre':>8} {'diff':>7} {'wall s':>7}")
    for scene in args.scene:
        if args.min_gap_ratio:
            scene = scene_with_min_gap_ratio(scene, args.min_gap_ratio)
        runs = [(scene, True)] + ([(scene_without_correction(scene), False)] if args.without
                                  else [])
        for path, corrected in runs:
            wall_s = 0.0
            if not args.no_run:
                wall_s, _ = run.run(args.build, path, *map(int, args.ranks.split(":")))
            s, trace = io.load_scene(path), io.trace_path(path)
            u_in, u_contact, u_film, st = restitution(path, io.read_trace_by_body(trace)[0])
            e_dry = s["dem"].get("material", {}).get("restitution", 0.9)
            # What the correction alone would leave of e / e_dry: one pass in, the dry contact,
            # one pass out (the same speed loss each way).
            du = correction_impulse(scene)
            only = max(0.0, (e_dry * max(0.0, u_in - du) - du) / (e_dry * u_in))
            e = u_film / u_in
            legendre = math.exp(-35 / st)
            diff = e / e_dry - legendre
            print(f"{s['name']:>22} {st:7.1f} {u_in:9.4g} {e / e_dry:8.4f} "
                  f"{u_contact / u_in / e_dry:8.4f} {only if corrected else 1.0:9.4f} "
                  f"{legendre:8.4f} {diff:+7.3f} {wall_s:7.1f}")
            validate_case.append_row(s["name"], f"{s['shapes'][0]['diameter'] / s['fluid']['dx']:.3g}",
                                     s["fluid"]["tau"], f"e/e_dry at St {st:.1f}",
                                     f"{legendre:.4g}", f"{e / e_dry:.4g}",
                                     f"{abs(diff):.4g}", wall_s, args.ranks.replace(":", "/"))
            if corrected:
                print(f"[validation] {s['name']}: |e/e_dry - exp(-35/St)| (Legendre et al.) at "
                      f"St {st:.1f} error {abs(diff):.4g}, tolerance {args.tolerance:g} (run "
                      f"time {wall_s:.1f} s)")
            if corrected and abs(diff) > args.tolerance:
                print(f"FAILED: |e/e_dry - exp(-35/St)| = {abs(diff):.3f} above {args.tolerance}")
                failed = 1
    print("e/e_dry: upward speed where the gap is back at h_c over U_in; contact: the first "
          "output after the reversal; corr.only: what the correction alone leaves")
    return failed


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    q = sub.add_parser("approach")
    q.add_argument("--build", required=True)
    q.add_argument("--scene", required=True)
    q.add_argument("--ranks", default="1:1")
    q.add_argument("--tolerance", type=float, default=1.0)
    q.add_argument("--case", help="name for results.csv (default: the scene's name)")
    q.add_argument("--no-run", action="store_true", help="analyse the existing trace only")
    b = sub.add_parser("bounce")
    b.add_argument("--build", required=True)
    b.add_argument("--scene", required=True, nargs="+")
    b.add_argument("--ranks", default="1:1")
    b.add_argument("--tolerance", type=float, default=1.0, help="on |e/e_dry - exp(-35/St)|")
    b.add_argument("--without", action="store_true", help="also run without the correction")
    b.add_argument("--no-run", action="store_true", help="analyse the existing traces only")
    b.add_argument("--min-gap-ratio", type=float, default=0.0,
                   help="run a copy of each scene with h_min = R x the sphere's radius")
    args = p.parse_args()
    lbdem_scene.use_build(args.build)  # values of scenes come from this build
    return {"approach": cmd_approach, "bounce": cmd_bounce}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
