"""Initial packings for the settling study, as the paper builds them (docs/study.md, "Packing"):
bodies on a simple cubic lattice at phi = 0.4, randomised, then positions scaled to each target
solid fraction; one packing serves spheres of diameter d and volume-equivalent cubes of edge
a = d (pi/6)^(1/3) with random orientations.

The randomising run is a hard-body Monte Carlo (Metropolis moves: a random displacement, and in
the last stage a random small rotation, rejected when the body would overlap another), not a DEM
run: each body is at once a sphere of diameter d and a cube of edge a, and a move is accepted
only if neither the spheres nor the cubes (separating-axis test) overlap, so the same positions
hold both shapes. Scaling positions up to a lower phi moves bodies apart and keeps them clear of
each other (the set of overlapping centre offsets of two convex bodies is star-shaped about 0).

Many bodies move at once on a checkerboard of cells (Anderson et al. 2013, J. Comput. Phys. 254,
"Massively parallel Monte Carlo for many-particle simulations on GPUs"): cells at least as wide
as the reach of a body (the cube's circumscribed diameter sqrt(3) a), an even number per axis,
coloured by the parities of their indices; in each round one body in every cell of one colour
tries a move that must keep it inside its cell, so two moving bodies are a whole cell apart and
never interact, and the round equals some sequential order of single moves. The grid is shifted
by a random vector each sweep so that the cell walls do not bias the positions. The overlap
tests run only for candidate pairs (bodies in the 27 cells around a moving one), vectorised
over all moving bodies of a round.
"""
import math
import time

import numpy as np

from . import geometry

PHI_START = 0.4
CUBE_PER_SPHERE = (math.pi / 6.0) ** (1.0 / 3.0)  # edge of the volume-equivalent cube / d
REACH_PER_SPHERE = math.sqrt(3.0) * CUBE_PER_SPHERE  # circumscribed diameter of the cube / d


def carnahan_starling_contact(phi):
    """g(d+) of hard spheres at solid fraction phi (Carnahan & Starling 1969):
    (1 - phi/2) / (1 - phi)^3."""
    return (1.0 - 0.5 * phi) / (1.0 - phi) ** 3


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

    def near_pairs(self, reach):
        """Every pair of bodies closer than `reach`, found afresh from the positions: (i, j, d)
        with d = x_j - x_i of the closest image. When the box holds two cells of width `reach`
        (so at most one image is that close), pairs from a fixed cell grid; otherwise every
        pair with every image shift that can come within reach, and each body with its own
        images (i == j), each pair of images once."""
        box = self.box
        x = self.x % box
        if box >= 2.0 * reach:
            nc = int(box // reach)
            flat, members = _cell_table(x, box, nc, np.zeros(3), -1)
            cells = np.stack(np.unravel_index(np.arange(nc**3), (nc,) * 3), -1)
            width = members.shape[1]
            out_i, out_j = [], []
            for o in {tuple(o % nc) for o in _OFFSETS}:  # nc = 2: offsets -1 and +1 coincide
                other = np.ravel_multi_index(((cells + o) % nc).T, (nc,) * 3)
                i = np.repeat(members[:, :, None], width, axis=2)
                j = np.repeat(members[other][:, None, :], width, axis=1)
                keep = (i >= 0) & (j >= 0) & (i < j)
                out_i.append(i[keep])
                out_j.append(j[keep])
            i, j = np.concatenate(out_i), np.concatenate(out_j)
            d = geometry.minimum_image(x[j] - x[i], np.full(3, box))
        else:
            shift = _image_shifts(reach, box)
            i, j = np.triu_indices(self.n)
            d = ((x[j] - x[i])[:, None, :] + shift[None]).reshape(-1, 3)
            i, j = np.repeat(i, len(shift)), np.repeat(j, len(shift))
            # A body and its image s is the pair of the image -s: keep s > 0 (lexicographic).
            positive = np.tile(np.lexsort(shift.T[::-1]).argsort() > len(shift) // 2, len(d)
                               // len(shift))
            keep = (i < j) | positive
            i, j, d = i[keep], j[keep], d[keep]
        keep = np.einsum("mi,mi->m", d, d) < reach * reach
        return i[keep], j[keep], d[keep]

    def overlaps(self):
        """(sphere pairs closer than d, cube pairs that overlap), over every pair and periodic
        image: an exact check made afresh from the positions and orientations (near_pairs and
        the normalised separating-axis test geometry.box_separation, not the generator's
        cell lists and test)."""
        i, j, dv = self.near_pairs(REACH_PER_SPHERE * self.d * (1 + 1e-9))
        r = np.linalg.norm(dv, axis=-1)
        spheres = int(np.count_nonzero(r < self.d * (1 - 1e-12)))
        rot = geometry.rotation_matrices(self.q)
        half = np.full(3, 0.5 * self.a)
        cubes = 0
        for c in range(0, len(i), 100000):
            s = slice(c, c + 100000)
            gaps = geometry.box_separation(dv[s], rot[i[s]], rot[j[s]], half, half)
            cubes += int(np.count_nonzero(gaps <= 0))
        return spheres, cubes

    def radial_distribution(self, r_max, bins):
        """g(r) up to r_max from near_pairs (so for any N): pairs per shell over the ideal-gas
        count N (N - 1) / 2 * shell volume / V. Returns (bin centres, g)."""
        edges = np.linspace(0.0, r_max, bins + 1)
        _, _, dv = self.near_pairs(r_max)
        counts = np.histogram(np.linalg.norm(dv, axis=-1), bins=edges)[0]
        shell = 4.0 / 3.0 * np.pi * (edges[1:] ** 3 - edges[:-1] ** 3)
        ideal = 0.5 * self.n * (self.n - 1) * shell / self.box**3
        return 0.5 * (edges[1:] + edges[:-1]), counts / ideal

    def contact_value(self):
        """g at contact of the spheres: g(r) in five bins over [d, 1.1 d], extrapolated linearly
        to r = d (the quantity of the hard-sphere references)."""
        r, g = self.radial_distribution(1.1 * self.d, 55)
        near = r > self.d
        return float(np.polyval(np.polyfit(r[near] / self.d, g[near], 1), 1.0))

    def order_parameter(self):
        """|sum exp(i k.x)| / N at the first reciprocal vector of the starting lattice, averaged
        over x, y, z: 1 on the lattice, ~1/sqrt(N) once the positions are random."""
        k = 2 * math.pi / self.spacing
        return float(np.mean([abs(np.exp(1j * k * self.x[:, c]).sum()) / self.n
                              for c in range(3)]))

    def save(self, path, phi_start, cubes=True, relaxed=None):
        """A bodies file (docs/study.md): HDF5 for a .h5 or .hdf5 path, else CSV."""
        from . import io
        write = io.write_bodies_h5 if path.endswith((".h5", ".hdf5")) else io.write_bodies_csv
        shapes = (f"sphere diameter {self.d!r} m, volume-equivalent cube edge {self.a!r} m"
                  if cubes else f"sphere diameter {self.d!r} m (spheres only: cubes not placed)")
        write(path, self.x, self.q, comment=(
            f"packing: {self.n} bodies, periodic box edge {self.box!r} m, solid fraction "
            f"{self.phi():.6g}\n{shapes}\nrandomised at phi {phi_start} by hard-body Monte Carlo "
            "(tools/lbdem/packing.py), then scaled" +
            (f", then relaxed there by {relaxed} sweeps of joint moves" if relaxed else "")))


_OFFSETS = np.array([(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)])


def _cell_table(x, box, nc, shift, pad):
    """Cell (flat index) of each position on an nc^3 grid displaced by `shift`, and the table
    (cells, most bodies in a cell) of the bodies per cell, `pad` where a cell has fewer."""
    c = np.minimum(((x - shift) % box / box * nc).astype(int), nc - 1)
    flat = np.ravel_multi_index(c.T, (nc,) * 3)
    order = np.argsort(flat, kind="stable")
    count = np.bincount(flat, minlength=nc**3)
    start = np.concatenate([[0], np.cumsum(count)[:-1]])
    members = np.full((nc**3, max(1, int(count.max()))), pad)
    members[flat[order], np.arange(len(x)) - start[flat[order]]] = order
    return flat, members


def _image_shifts(reach, box):
    """Periodic image shifts (S, 3) that can bring two points of the box within `reach`."""
    m = math.ceil(reach / box)
    s = np.arange(-m, m + 1)
    return box * np.stack(np.meshgrid(s, s, s, indexing="ij"), -1).reshape(-1, 3)


class _Moves:
    """Trial moves of the bodies of a packing in checkerboard rounds (module docstring), with
    the overlap tests for candidate pairs only. Spheres of diameter d always; with `cubes` the
    cubes too, which widens the cells to the cube's reach."""

    def __init__(self, p, rng, cubes):
        self.p, self.rng, self.cubes = p, rng, cubes
        self.reach = REACH_PER_SPHERE * p.d if cubes else p.d
        self.half = np.full(3, 0.5 * p.a)
        self.margin = 1e-9 * p.d  # touching counts as overlapping: the exact check agrees
        self.rot = geometry.rotation_matrices(p.q)
        self.count = np.zeros(p.n, int)
        # Positions with one padding row (index n) for the candidate tables; p.x views it.
        self.xp = np.vstack([p.x, np.zeros((1, 3))])
        p.x = self.xp[:-1]
        self.nc = 2 * int(p.box // (2.0 * self.reach))  # even: colours alternate round the box
        if self.nc >= 2:
            nc = self.nc
            cells = np.stack(np.unravel_index(np.arange(nc**3), (nc,) * 3), -1)
            nbr = np.ravel_multi_index(((cells[:, None, :] + _OFFSETS) % nc).T, (nc,) * 3).T
            self.nbr = np.array([np.unique(row) for row in nbr]) if nc == 2 else nbr
            self.colour = (cells % 2) @ np.array([1, 2, 4])
        else:
            # A box narrower than two reaches: one body at a time against every image of the
            # others (a body never reaches its own image once the box is wider than the reach,
            # which 3 bodies at phi 0.4 give).
            shift = _image_shifts(self.reach, p.box)
            self.img_j = np.repeat(np.arange(p.n), len(shift))
            self.img_s = np.tile(shift, (p.n, 1))

    def _separations(self, k, xn, cand):
        """Offsets (m, K, 3) from trial positions xn of bodies k to their candidates cand
        (m, K) (index n: none) and the squared lengths, infinite for self and padding."""
        p = self.p
        if self.nc >= 2:
            dv = geometry.minimum_image(self.xp[cand] - xn[:, None, :], np.full(3, p.box))
        else:
            dv = self.xp[cand] + self.img_s[None] - xn[:, None, :]
        r2 = np.einsum("mki,mki->mk", dv, dv)
        r2[(cand == p.n) | (cand == k[:, None])] = np.inf
        return dv, r2

    def _cube_partners(self, rows, dv, r2, cand, rot_k):
        """(row, column) of the candidates whose cubes overlap those of the bodies in `rows`:
        circumscribed spheres first, the separating-axis test for the pairs they leave."""
        r, c = np.nonzero((r2 < self.reach**2) & rows[:, None])
        sep = geometry.boxes_separated(dv[r, c], rot_k[r], self.rot[cand[r, c]], self.half,
                                       self.half, self.margin)
        return r[~sep], c[~sep]

    def _try(self, k, xn, qn, cand, ok, rule, tries=1):
        """Moves bodies k to (xn, qn) where `ok` and the spheres stay clear and the cubes obey
        `rule`: "none" (no cube overlap) or "fewer" (no more overlaps than the body has now,
        self.count kept up to date; a body clear of overlaps stays clear). With `tries` > 1
        the rows are `tries` trial poses per body (body-major) and a body takes the first of
        those with the fewest overlaps; as rejected trials change nothing, that is the outcome
        of trying them one after another until the best one. Returns the number of moves."""
        p = self.p
        dv, r2 = self._separations(k, xn, cand)
        ok = ok & ~(r2 < p.d * p.d).any(axis=1)
        new = np.zeros(len(k), int)
        if self.cubes and np.any(ok):
            rot_n = geometry.rotation_matrices(qn)
            r_new, c_new = self._cube_partners(ok, dv, r2, cand, rot_n)
            new = np.bincount(r_new, minlength=len(k))
            ok &= new == 0 if rule == "none" else new <= self.count[k]
        if tries > 1:
            score = np.where(ok, new, np.iinfo(int).max).reshape(-1, tries)
            pick = np.arange(0, len(k), tries) + score.argmin(axis=1)
            chosen = np.zeros(len(k), bool)
            chosen[pick] = True
            ok &= chosen
        if self.cubes and np.any(ok):
            if rule == "fewer":
                dv0, r20 = self._separations(k, p.x[k], cand)
                r_old, c_old = self._cube_partners(ok, dv0, r20, cand, self.rot[k])
                np.subtract.at(self.count, cand[r_old, c_old], 1)
                keep = ok[r_new]
                np.add.at(self.count, cand[r_new[keep], c_new[keep]], 1)
                self.count[k[ok]] = new[ok]
            self.rot[k[ok]] = rot_n[ok]
        p.x[k[ok]] = xn[ok] % p.box
        p.q[k[ok]] = qn[ok] / np.linalg.norm(qn[ok], axis=1, keepdims=True)
        return int(np.count_nonzero(ok))

    def cube_counts(self):
        """Sets self.count to the cube overlaps of every body (the generator's own test)."""
        p = self.p
        self.count[:] = 0
        if self.nc < 2:
            parts = [(np.array([k]), self.img_j[None]) for k in range(p.n)]
        else:
            flat, members = _cell_table(p.x, p.box, self.nc, np.zeros(3), p.n)
            cand = members[self.nbr].reshape(len(members), -1)
            parts = [(k, cand[flat[k]]) for k in np.array_split(np.arange(p.n),
                                                                 max(1, p.n // 4096))]
        for k, cand in parts:
            dv, r2 = self._separations(k, p.x[k], cand)
            r, _ = self._cube_partners(np.ones(len(k), bool), dv, r2, cand, self.rot[k])
            np.add.at(self.count, k[r], 1)
        return self.count

    def around(self, mask):
        """The bodies in the 27 cells around the bodies in `mask` (all with fewer than 2 cells
        per axis)."""
        if self.nc < 2:
            return np.ones(self.p.n, bool)
        flat, _ = _cell_table(self.p.x, self.p.box, self.nc, np.zeros(3), -1)
        near = np.zeros(self.nc**3, bool)
        near[self.nbr[flat[mask]].ravel()] = True
        return near[flat]

    def sweep(self, propose, rule, movable, tries=1, reach=None):
        """About one trial move per movable body, each of `tries` trial poses (see _try):
        `propose(k)` gives trial (x, q) of bodies k. With several tries, a body's candidates
        are first narrowed to those within `reach` (the test's reach plus the longest
        displacement) of where it is. Returns (trial poses, moves made)."""
        p, rng, nc = self.p, self.rng, self.nc
        tried = moved = 0
        if nc < 2:
            for k in rng.permutation(np.flatnonzero(movable)):
                k = np.full(tries, k)
                xn, qn = propose(k)
                tried += tries
                moved += self._try(k, xn, qn, np.repeat(self.img_j[None], tries, axis=0),
                                   np.ones(tries, bool), rule, tries)
            return tried, moved
        shift = rng.random(3) * p.box / nc
        flat, members = _cell_table(p.x, p.box, nc, shift, p.n)
        mine = np.flatnonzero(movable)
        if len(mine) == 0:
            return 0, 0
        _, movers = _cell_table(p.x[mine], p.box, nc, shift, -1)
        movers = np.where(movers >= 0, mine[movers], p.n)
        n_movers = np.count_nonzero(movers < p.n, axis=1)
        rounds = max(1, round(len(mine) / max(1, np.count_nonzero(n_movers))))
        for colour in rng.permutation(8):
            act = np.flatnonzero((self.colour == colour) & (n_movers > 0))
            if len(act) == 0:
                continue
            cand = np.sort(members[self.nbr[act]].reshape(len(act), -1), axis=1)
            cand = cand[:, :int(np.count_nonzero(cand < p.n, axis=1).max())]
            for _ in range(rounds):
                k = movers[act, (rng.random(len(act)) * n_movers[act]).astype(int)]
                near = cand
                if tries > 1:
                    _, r2 = self._separations(k, p.x[k], cand)
                    near = np.where(r2 < reach * reach, cand, p.n)
                    near = np.sort(near, axis=1)
                    near = near[:, :max(1, int(np.count_nonzero(near < p.n, axis=1).max()))]
                k = np.repeat(k, tries)
                xn, qn = propose(k)
                c = np.minimum(((xn - shift) % p.box / p.box * nc).astype(int), nc - 1)
                in_cell = np.ravel_multi_index(c.T, (nc,) * 3) == np.repeat(act, tries)
                tried += len(k)
                moved += self._try(k, xn, qn, np.repeat(near, tries, axis=0), in_cell, rule,
                                   tries)
        return tried, moved


def randomise(p, sweeps, seed, log=print, cubes=True):
    """Randomises packing p in place, in three stages:
    1. hard-sphere Monte Carlo, sweeps of about N displacements (distances only): `sweeps`
       of them, and on until the lattice order is below 3/sqrt(N) (at most 10 x sweeps);
    2. uniformly random cube orientations (Shoemake); passes in which a cube that overlaps a
       neighbour tries 20 poses (half a new random orientation with a displacement of up to
       0.2 d, half a joint move as in stage 3) and takes the one with the fewest overlaps if
       the spheres stay clear and its overlaps do not increase, each pass followed by 20 such
       tries for every body near an overlap (a clear body by joint moves that keep it clear),
       until none overlaps;
    3. sweeps/10 sweeps of moves that displace and rotate a body together, accepted only when
       neither spheres nor cubes overlap, so the orientations lose the bias of stage 2.
    Without `cubes` only stage 1 (orientations left aligned). Returns the acceptance ratios of
    stages 1 and 3 (None without cubes)."""
    rng = np.random.default_rng(seed)
    step = 0.2 * p.d
    everyone = np.ones(p.n, bool)
    t0 = time.monotonic()

    def displaced(k, size):
        return p.x[k] + size * (2 * rng.random((len(k), 3)) - 1)

    spheres = _Moves(p, rng, cubes=False)
    tried = moved = sweep = 0
    block = max(1, sweeps // 4)
    random_order = 3.0 / math.sqrt(p.n)
    while sweep < sweeps or (p.order_parameter() > random_order and sweep < 10 * sweeps):
        t, m = spheres.sweep(lambda k: (displaced(k, step), p.q[k]), "none", everyone)
        tried, moved, sweep = tried + t, moved + m, sweep + 1
        if sweep % block == 0:
            log(f"packing: sphere sweep {sweep} (of at least {sweeps}), acceptance "
                f"{moved / tried:.2f}, "
                f"lattice order {p.order_parameter():.3f} (random: below "
                f"{random_order:.3f}), {time.monotonic() - t0:.1f} s")
    log(f"packing: hard spheres after {sweep} sweeps: g(d+) {p.contact_value():.2f} "
        f"(Carnahan-Starling at phi {PHI_START}: {carnahan_starling_contact(PHI_START):.2f})")
    sphere_acceptance = moved / max(tried, 1)
    if not cubes:
        return sphere_acceptance, None

    t1 = time.monotonic()
    p.q = geometry.random_quaternions(rng, p.n)
    mv = _Moves(p, rng, cubes=True)
    angle = 0.5

    def rotated(k):
        axis = rng.standard_normal((len(k), 3))
        axis /= np.linalg.norm(axis, axis=1, keepdims=True)
        h = 0.5 * angle * (2 * rng.random(len(k)) - 1)
        turn = np.concatenate([np.cos(h)[:, None], np.sin(h)[:, None] * axis], axis=1)
        return displaced(k, 0.5 * step), geometry.quaternion_multiply(turn, p.q[k])

    def redrawn(k):
        # Half the trials a new random orientation, half a joint move: a body left with few
        # overlaps in a tight cage then walks among poses with no more overlaps to a free one.
        x, q = rotated(k)
        new = rng.random(len(k)) < 0.5
        x[new] = displaced(k[new], step)
        q[new] = geometry.random_quaternions(rng, int(np.count_nonzero(new)))
        return x, q

    def redrawn_or_rotated(k):
        x, q = rotated(k)
        over = mv.count[k] > 0
        x[over], q[over] = redrawn(k[over])
        return x, q

    # Passes of 20 redraws per overlapping body; after each, 20 moves per body in the cells
    # around the overlapping ones (those redrawn, the others by joint moves that keep them
    # clear), so that the neighbours of a jammed pair make room.
    reach = mv.reach + math.sqrt(3.0) * step
    redraws = passes = 0
    while mv.cube_counts().any():  # the kept counts reach zero; a full count confirms it
        while mv.count.any():
            redraws += mv.sweep(redrawn, "fewer", mv.count > 0, 20, reach)[0]
            if mv.count.any():
                mv.sweep(redrawn_or_rotated, "fewer", mv.around(mv.count > 0), 20, reach)
            passes += 1
            if passes % 10 == 0:
                log(f"packing: orientation pass {passes}, {np.count_nonzero(mv.count)} bodies "
                    f"overlap, {time.monotonic() - t1:.1f} s")
            if redraws > 2000 * p.n:
                raise RuntimeError("packing: cannot orient the cubes without overlaps")
    log(f"packing: random cube orientations, {redraws} redraws in {passes} passes to clear the "
        f"overlaps, {time.monotonic() - t1:.1f} s")

    t2 = time.monotonic()
    tried = moved = 0
    for _ in range(max(1, sweeps // 10)):
        t, m = mv.sweep(rotated, "none", everyone)
        tried, moved = tried + t, moved + m
    log(f"packing: {max(1, sweeps // 10)} sweeps of joint moves, acceptance "
        f"{moved / max(tried, 1):.2f}, lattice order {p.order_parameter():.3f}, g(d+) "
        f"{p.contact_value():.2f}, {time.monotonic() - t2:.1f} s")
    return sphere_acceptance, moved / max(tried, 1)


def relax_step(phi):
    """Largest displacement per axis of a relaxing move, in d: the mean gap between neighbours
    on a simple cubic lattice at phi, (pi / (6 phi))^(1/3) - 1 (0.74 at phi 0.1, 0.20 at 0.3),
    within [0.1, 0.5], so that a fair share of the moves is accepted at every phi."""
    return min(0.5, max(0.1, (math.pi / (6.0 * phi)) ** (1.0 / 3.0) - 1.0))


def relax(p, sweeps, seed, step=0.5, angle=0.5, log=print):
    """Randomises packing p in place at its own solid fraction: `sweeps` sweeps of joint moves
    (a displacement of up to `step` d per axis and a rotation of up to `angle` rad), accepted
    only when neither spheres nor cubes overlap. A packing scaled down from phi 0.4 is the
    denser packing magnified (no two centres closer than (0.4 / phi)^(1/3) d); these moves
    draw it from the hard-body fluid at the target phi instead (the Metropolis chain's
    stationary distribution: every overlap-free configuration equally likely). Returns the
    acceptance ratio and the rms displacement (unwrapped) in d."""
    rng = np.random.default_rng(seed)
    mv = _Moves(p, rng, cubes=True)
    start = p.x.copy()
    moved_by = np.zeros_like(start)  # unwrapped displacement, the positions wrap at the box

    def proposed(k):
        axis = rng.standard_normal((len(k), 3))
        axis /= np.linalg.norm(axis, axis=1, keepdims=True)
        h = 0.5 * angle * (2 * rng.random(len(k)) - 1)
        turn = np.concatenate([np.cos(h)[:, None], np.sin(h)[:, None] * axis], axis=1)
        return (p.x[k] + step * p.d * (2 * rng.random((len(k), 3)) - 1),
                geometry.quaternion_multiply(turn, p.q[k]))

    t0 = time.monotonic()
    tried = moved = 0
    for _ in range(sweeps):
        before = p.x.copy()
        t, m = mv.sweep(proposed, "none", np.ones(p.n, bool))
        tried, moved = tried + t, moved + m
        moved_by += geometry.minimum_image(p.x - before, np.full(3, p.box))
    rms = float(np.sqrt(np.mean(np.einsum("ij,ij->i", moved_by, moved_by)))) / p.d
    log(f"packing: relaxed at phi {p.phi():.4f}: {sweeps} sweeps of joint moves (up to "
        f"{step:.2f} d, {angle:g} rad), acceptance {moved / max(tried, 1):.2f}, rms displacement "
        f"{rms:.2f} d, lattice order {p.order_parameter():.3f}, {time.monotonic() - t0:.1f} s")
    return moved / max(tried, 1), rms


def make_packing(count, sweeps, seed, d=1.0, log=print, cubes=True):
    """The randomised phi = 0.4 packing of `count` bodies of diameter d (and cubes of edge a;
    spheres only without `cubes`)."""
    p = Packing(count, PHI_START, d, seed)
    randomise(p, sweeps, seed, log, cubes)
    return p
