#!/usr/bin/python3
"""Writes the study's initial packings (docs/study.md, "Packing"): N bodies on a simple cubic
lattice at phi = 0.4, randomised by hard-body Monte Carlo (spheres of diameter d and
volume-equivalent cubes at once), scaled to each solid fraction; one bodies file per phi for
the scene key `bodies: [{file: ..., shape: ..., density: ...}]`.

    /usr/bin/python3 tools/make_packing.py --bodies 27 --diameter 3.5e-4 --phi 0.1 0.3 \
        --sweeps 1000 --seed 1 --out runs/packing

Prints per file the box edge, the measured phi, the overlaps (spheres, cubes), the lattice order
left and g(r) at contact.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lbdem import analysis, packing  # noqa: E402


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
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    base = packing.make_packing(args.bodies, args.sweeps, args.seed, args.diameter)
    for phi in [packing.PHI_START] + args.phi:
        s = base.scaled(phi)
        path = os.path.join(args.out, f"packing_phi{phi:.3f}.{args.format}")
        s.save(path, packing.PHI_START)
        r, g = analysis.radial_distribution(s.x, np.full(3, s.box), bins=20)
        contact = g[r > s.d][0] if np.any(r > s.d) else float("nan")
        print(f"{path}: {s.n} bodies, box {s.box:.6g} m, phi {s.phi():.4f}, overlaps (spheres, "
              f"cubes) {s.overlaps()}, lattice order {s.order_parameter():.3f}, g at contact "
              f"{contact:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
