"""Initial packings for the settling study, as the paper builds them (docs/study.md, "Packing"):
bodies on a simple cubic lattice at phi = 0.4, randomised, then positions scaled to each target
solid fraction; one packing serves spheres of diameter d and volume-equivalent cubes of edge
a = d (pi/6)^(1/3) with random orientations.

The randomising run is a hard-body Monte Carlo (Metropolis moves of one body at a time: a random
displacement and a random small rotation, rejected when the body would overlap another), not a
DEM run: each body is at once a sphere of diameter d and a cube of edge a, and a move is accepted
only if neither the spheres nor the cubes (separating-axis test) overlap, so the same positions
hold both shapes. Moves are sized for about 40 % acceptance. Scaling positions up to a lower phi
moves bodies apart and keeps them clear of each other.
"""
import math

import numpy as np

from . import geometry

PHI_START = 0.4
CUBE_PER_SPHERE = (math.pi / 6.0) ** (1.0 / 3.0)  # edge of the volume-equivalent cube / d


class Packing:
    """`count` bodies in a periodic cube of edge `box` at solid fraction phi (spheres of diameter
    d): a simple cubic lattice of ceil(count^(1/3))^3 sites filling the box, with the sites beyond
    `count` left empty (chosen at random with `seed`), all cubes aligned."""

    def __init__(self, count, phi=PHI_START, d=1.0, seed=0):
        self.d = d
        self.a = CUBE_PER_SPHERE * d
        self.box = (count * math.pi / 6.0 * d**3 / phi) ** (1.0 / 3.0)
        n_side = math.ceil(round(count ** (1.0 / 3.0), 9))
        self.spacing = self.box / n_side
        g = (np.arange(n_side) + 0.5) * self.spacing
        sites = np.stack(np.meshgrid(g, g, g, indexing="ij"), -1).reshape(-1, 3)
        if len(sites) > count:
            keep = np.sort(np.random.default_rng(seed).permutation(len(sites))[:count])
            sites = sites[keep]
        self.x = sites
        self.q = np.tile([1.0, 0.0, 0.0, 0.0], (count, 1))

    @property
    def n(self):
        return len(self.x)

    def phi(self):
        return self.n * math.pi / 6.0 * self.d**3 / self.box**3

    def scaled(self, phi):
        """Positions and box scaled to solid fraction phi <= the current one (orientations kept)."""
        if phi > self.phi() + 1e-12:
            raise ValueError(f"cannot compress the packing from phi {self.phi():.4g} to {phi:.4g}")
        s = (self.phi() / phi) ** (1.0 / 3.0)
        out = Packing.__new__(Packing)
        out.d, out.a, out.spacing = self.d, self.a, self.spacing * s
        out.box, out.x, out.q = self.box * s, self.x * s, self.q.copy()
        return out

    def overlaps(self):
        """(sphere pairs closer than d, cube pairs that overlap) over all pairs, minimum image."""
        box = np.full(3, self.box)
        i, j, dv = geometry.pair_separations(self.x, box)
        r = np.linalg.norm(dv, axis=-1)
        spheres = int(np.count_nonzero(r < self.d * (1 - 1e-12)))
        near = r < math.sqrt(3.0) * self.a
        rot = geometry.rotation_matrices(self.q)
        half = np.full(3, 0.5 * self.a)
        gaps = geometry.box_separation(dv[near], rot[i[near]], rot[j[near]], half, half)
        return spheres, int(np.count_nonzero(gaps <= 0))

    def order_parameter(self):
        """|sum exp(i k.x)| / N at the first reciprocal vector of the starting lattice, averaged
        over x, y, z: 1 on the lattice, ~1/sqrt(N) once the positions are random."""
        k = 2 * math.pi / self.spacing
        return float(np.mean([abs(np.exp(1j * k * self.x[:, c]).sum()) / self.n
                              for c in range(3)]))

    def save(self, path, phi_start):
        """A bodies file (docs/study.md): HDF5 for a .h5 or .hdf5 path, else CSV."""
        from . import io
        write = io.write_bodies_h5 if path.endswith((".h5", ".hdf5")) else io.write_bodies_csv
        write(path, self.x, self.q, comment=(
            f"packing: {self.n} bodies, periodic box edge {self.box!r} m, solid fraction "
            f"{self.phi():.6g}\nsphere diameter {self.d!r} m, volume-equivalent cube edge "
            f"{self.a!r} m\nrandomised at phi {phi_start} by hard-body Monte Carlo "
            "(tools/lbdem/packing.py), then scaled"))


class _Neighbours:
    """Cell list over the periodic box (cells at least `reach` wide); all bodies when the box
    holds fewer than 3 cells per axis."""

    def __init__(self, x, box, reach):
        self.box, self.n = box, len(x)
        self.nc = int(box // reach)
        self.cell = np.floor(x / box * self.nc).astype(int) % max(self.nc, 1)
        self.members = {}
        if self.nc >= 3:
            for k, c in enumerate(map(tuple, self.cell)):
                self.members.setdefault(c, set()).add(k)

    def around(self, k, x):
        if self.nc < 3:
            return np.delete(np.arange(self.n), k)
        c = np.floor(x / self.box * self.nc).astype(int) % self.nc
        out = set()
        for o in _OFFSETS:
            out |= self.members.get(tuple((c + o) % self.nc), set())
        out.discard(k)
        return np.fromiter(out, int)

    def move(self, k, x):
        if self.nc < 3:
            return
        c = tuple(np.floor(x / self.box * self.nc).astype(int) % self.nc)
        old = tuple(self.cell[k])
        if old != c:
            self.members[old].discard(k)
            self.members.setdefault(c, set()).add(k)
            self.cell[k] = c


_OFFSETS = np.array([(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])


def _cube_gaps(p, k, x, q, cand, rot):
    """Separating-axis gaps between cube k (at x, q) and the cubes `cand` near it."""
    dv = geometry.minimum_image(p.x[cand] - x, np.full(3, p.box))
    near = np.linalg.norm(dv, axis=-1) < math.sqrt(3.0) * p.a
    if not np.any(near):
        return np.zeros(0)
    m = int(np.count_nonzero(near))
    half = np.full(3, 0.5 * p.a)
    rq = np.broadcast_to(geometry.rotation_matrices(q), (m, 3, 3))
    return geometry.box_separation(dv[near], rq, rot[cand[near]], half, half)


def randomise(p, sweeps, seed, log=print):
    """Randomises packing p in place, in three stages:
    1. hard-sphere Monte Carlo, `sweeps` x N single-body displacements (cheap: distances only);
    2. uniformly random cube orientations (Shoemake); a cube that then overlaps a neighbour is
       given new random orientations (and displacements of up to 0.02 d) until none overlaps;
    3. sweeps/10 sweeps of moves that displace and rotate a body together, accepted only when
       neither spheres nor cubes overlap, so the orientations lose the bias of stage 2.
    Returns the acceptance ratios of stages 1 and 3."""
    rng = np.random.default_rng(seed)
    box = np.full(3, p.box)
    nb = _Neighbours(p.x, p.box, max(p.d, math.sqrt(3.0) * p.a))
    step = 0.2 * p.d

    def sphere_free(k, x):
        cand = nb.around(k, x)
        dv = geometry.minimum_image(p.x[cand] - x, box)
        return cand, not np.any(np.einsum("mi,mi->m", dv, dv) < p.d * p.d)

    tried = moved = 0
    for sweep in range(sweeps):
        for k in rng.integers(0, p.n, p.n):
            x_new = (p.x[k] + step * (2 * rng.random(3) - 1)) % p.box
            tried += 1
            if sphere_free(k, x_new)[1]:
                nb.move(k, x_new)
                p.x[k] = x_new
                moved += 1
        if (sweep + 1) % max(1, sweeps // 4) == 0:
            log(f"packing: sphere sweep {sweep + 1}/{sweeps}, acceptance {moved / tried:.2f}, "
                f"lattice order {p.order_parameter():.3f}")
    sphere_acceptance = moved / max(tried, 1)

    p.q = geometry.random_quaternions(rng, p.n)
    rot = geometry.rotation_matrices(p.q)

    def cube_overlaps(k, x, q):
        cand, free = sphere_free(k, x)
        return cand, free, int(np.count_nonzero(_cube_gaps(p, k, x, q, cand, rot) <= 0))

    # Clear the cube overlaps: a body that overlaps gets a new random orientation and a small
    # displacement, kept when no sphere overlaps and its cube overlaps do not increase.
    redraws = 0
    while True:
        counts = np.array([cube_overlaps(k, p.x[k], p.q[k])[2] for k in range(p.n)])
        if not counts.any():
            break
        for k in np.flatnonzero(counts):
            for _ in range(20):
                x_new = (p.x[k] + 0.1 * step * (2 * rng.random(3) - 1)) % p.box
                q_new = geometry.random_quaternions(rng, 1)[0]
                _, free, c = cube_overlaps(k, x_new, q_new)
                redraws += 1
                if free and c <= counts[k]:
                    nb.move(k, x_new)
                    p.x[k], p.q[k] = x_new, q_new
                    rot[k] = geometry.rotation_matrices(q_new)
                    if c == 0:
                        break
                    counts[k] = c
        if redraws > 2000 * p.n:
            raise RuntimeError("packing: cannot orient the cubes without overlaps")
    log(f"packing: random cube orientations, {redraws} redraws to clear the overlaps")

    tried = moved = 0
    angle = 0.5
    for sweep in range(max(1, sweeps // 10)):
        for k in rng.integers(0, p.n, p.n):
            x_new = (p.x[k] + 0.5 * step * (2 * rng.random(3) - 1)) % p.box
            axis = rng.standard_normal(3)
            axis /= np.linalg.norm(axis)
            h = 0.5 * angle * (2 * rng.random() - 1)
            q_new = geometry.quaternion_multiply(
                np.concatenate([[math.cos(h)], math.sin(h) * axis]), p.q[k])
            tried += 1
            cand, free = sphere_free(k, x_new)
            if not free or np.any(_cube_gaps(p, k, x_new, q_new, cand, rot) <= 0):
                continue
            nb.move(k, x_new)
            p.x[k], p.q[k] = x_new, q_new
            rot[k] = geometry.rotation_matrices(q_new)
            moved += 1
    log(f"packing: {max(1, sweeps // 10)} sweeps of joint moves, acceptance "
        f"{moved / max(tried, 1):.2f}, lattice order {p.order_parameter():.3f}")
    return sphere_acceptance, moved / max(tried, 1)


def make_packing(count, sweeps, seed, d=1.0, log=print):
    """The randomised phi = 0.4 packing of `count` bodies of diameter d (and cubes of edge a)."""
    p = Packing(count, PHI_START, d, seed)
    randomise(p, sweeps, seed, log)
    return p
