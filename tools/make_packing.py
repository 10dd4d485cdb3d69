#!/usr/bin/python3
"""Writes the study's initial packings (docs/study.md, "Packing"): N bodies on a simple cubic
lattice at phi = 0.4, randomised by hard-body Monte Carlo (spheres of diameter d and
volume-equivalent cubes at once, moved many at a time on a checkerboard of cells), scaled to
each solid fraction and, with --relax, randomised there again; one bodies file per phi for the
scene key `bodies: [{file: ..., shape: ..., density: ...}]`.

    /usr/bin/python3 tools/make_packing.py --bodies 27 --diameter 3.5e-4 --phi 0.1 0.3 \\
        --sweeps 1000 --seed 1 --relax 1000 --out runs/packing

Prints the time of each stage of the Monte Carlo and in all; the contact value g(d+) of the
hard-sphere stage beside the Carnahan-Starling value at phi 0.4 and of the final packing; per
file the box edge, the measured phi, the overlaps (spheres, cubes; an exact check over every
pair and image, separate from the generator's) and the lattice order left. --spheres-only stops
after the hard-sphere stage (orientations left aligned). --vs REV also runs the generator of git
revision REV on the same bodies and sweeps, stopped after --vs-limit seconds, and prints both
times.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import packing  # noqa: E402

_OLD_RUN = """
import sys, time
sys.path.insert(0, sys.argv[1])
from lbdem import packing
t0 = time.monotonic()
packing.make_packing(int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), float(sys.argv[5]),
                     log=lambda s: print(f"{time.monotonic() - t0:.1f} s: {s}", flush=True))
print(f"done in {time.monotonic() - t0:.1f} s", flush=True)
"""


def time_revision(rev, args):
    """Runs the packing generator of git revision `rev` (its tools/lbdem) on the same bodies,
    sweeps and seed, stopped after args.vs_limit seconds; prints its log. Returns (seconds,
    its last line)."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with tempfile.TemporaryDirectory() as tmp:
        os.makedirs(os.path.join(tmp, "lbdem"))
        for name in ("__init__.py", "packing.py", "geometry.py"):
            text = subprocess.run(["git", "-C", root, "show", f"{rev}:tools/lbdem/{name}"],
                                  check=True, capture_output=True, text=True).stdout
            with open(os.path.join(tmp, "lbdem", name), "w") as f:
                f.write(text)
        t0 = time.monotonic()
        cmd = [sys.executable, "-c", _OLD_RUN, tmp, str(args.bodies), str(args.sweeps),
               str(args.seed), repr(args.diameter)]
        lines = []
        with subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True) as proc:
            try:
                out, _ = proc.communicate(timeout=args.vs_limit)
                lines = out.splitlines()
            except subprocess.TimeoutExpired:
                proc.kill()
                out, _ = proc.communicate()
                lines = out.splitlines() + [f"stopped after {args.vs_limit:.0f} s"]
        for line in lines:
            print(f"revision {rev}: {line}")
        return time.monotonic() - t0, (lines or ["no output"])[-1]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("--bodies", type=int, required=True)
    p.add_argument("--diameter", type=float, default=3.5e-4, help="sphere diameter in m")
    p.add_argument("--phi", type=float, nargs="+", required=True)
    p.add_argument("--sweeps", type=int, default=1000)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--out", required=True)
    p.add_argument("--format", choices=["csv", "h5"], default="csv",
                   help="bodies file format (docs/study.md, 'Bodies from a file')")
    p.add_argument("--spheres-only", action="store_true",
                   help="hard-sphere stage only (cubes not placed, orientations aligned)")
    p.add_argument("--relax", type=int, default=0, metavar="SWEEPS",
                   help="relax each scaled packing at its phi by SWEEPS sweeps of joint moves "
                        "(packing.relax; what tools/study.py does, 'packing.relax_sweeps')")
    p.add_argument("--vs", metavar="REV", help="also time the generator of git revision REV")
    p.add_argument("--vs-limit", type=float, default=600.0, metavar="S",
                   help="stop the generator of --vs after S seconds (default 600)")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    cubes = not args.spheres_only
    t0, c0 = time.monotonic(), time.process_time()
    base = packing.make_packing(args.bodies, args.sweeps, args.seed, args.diameter,
                                cubes=cubes)
    made, cpu = time.monotonic() - t0, time.process_time() - c0
    print(f"packing: {args.bodies} {'bodies' if cubes else 'spheres'}, {args.sweeps} sweeps, "
          f"made in {made:.1f} s ({cpu:.1f} s of CPU)")
    for phi in [packing.PHI_START] + args.phi:
        s = base.scaled(phi)
        relaxed = args.relax if args.relax and phi < packing.PHI_START else None
        if relaxed:
            packing.relax(s, relaxed, args.seed, packing.relax_step(phi))
        path = os.path.join(args.out, f"packing_phi{phi:.3f}.{args.format}")
        s.save(path, packing.PHI_START, cubes, relaxed)
        t1 = time.monotonic()
        spheres, cube_pairs = s.overlaps()
        checked = time.monotonic() - t1
        print(f"{path}: {s.n} bodies, box {s.box:.6g} m, phi {s.phi():.4f}, overlaps (spheres, "
              f"cubes) ({spheres}, {cube_pairs if cubes else 'not placed'}) [exact check "
              f"{checked:.1f} s], lattice order {s.order_parameter():.3f}")
        if spheres or (cubes and cube_pairs):
            print(f"{path}: the packing has overlaps", file=sys.stderr)
            return 1
    if args.vs:
        old, last = time_revision(args.vs, args)
        print(f"packing time: this generator {made:.1f} s, revision {args.vs} {old:.1f} s "
              f"({last})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
