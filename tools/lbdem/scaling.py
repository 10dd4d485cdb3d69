"""Cost model of a coupled step from the per-rank counters of the run summaries
(docs/scaling.md, "Cost model"; tools/scaling.py runs it).

A fluid rank's busy time per step (lattice + porosity and momentum exchange) is a sum over its
counters times per-unit costs:

    busy = c_cell cells + c_row porous_row_cells            (lattice: every cell, and the
         + c_cov covered_cells                               cells of rows on a porous path,
                                                             and the covered cells)
         + c_pcov covered_cells + c_body bodies_in_table     (porosity and momentum exchange)
         + c_halo halo_bytes_per_step                        (halo packing and messages)

(the band and the interiors are counted apart, but one cube size holds them in a fixed ratio:
the fit takes their sum, the covered cells). The lattice kernel runs a whole row of cells along
x on a porous path as soon as one of its cells is covered (fluid_app/kernel/aa_kernel.hpp,
porous_row): c_row is what such a row's cell costs beyond a cell of a fluid row, and the fit
scenes hold aligned cubes (few rows per covered cell) and rotated ones (many). The porosity part
of a rotated cube costs more per covered cell than an aligned one's (1.4-1.7 x measured), which
no counter shows: c_pcov and c_body are fitted on the rotated scenes only, as the suspensions
the model predicts are randomly oriented.

its coupler exchange c_x + c_byte x coupler_bytes_per_step (a fixed part per step: the counts
all-to-all, the calls), and a DEM rank's busy time c_dem + c_atom x (atoms + ghost_atoms) x
substeps. On cores of their own the programs overlap their work and the coupled step takes the
longer side, max(max_r fluid busy + exchange, max_r DEM busy + exchange); where they share cores
(this machine) the sum of the two is the other bound.

The costs are fitted by non-negative least squares on runs measured on one core; the counters
of a layout never run come from its geometry (`uniform_counters`): cells of the blocks, bodies
whose reach meets a block (the Minkowski sum of the block and a ball), the rows a randomly
oriented suspension covers (`porous_row_fraction`), the halo links of the
D3Q19 lattice (`halo_values`), 200 coupler bytes per body in a rank's table (a 128-byte state
in, a 72-byte load out).
"""
import math

import numpy as np

STATE_BYTES, LOAD_BYTES = 128, 72  # sizeof(BodyState), sizeof(BodyLoad)
FLUID_COSTS = ("cell", "porous_row", "covered", "porosity_cell", "body",
               "halo_byte")  # of fluid_busy
FLUID_TERMS = ("cells", "porous_row_cells", "covered_cells", "band_cells", "body_interior_cells",
               "bodies_in_table", "halo_bytes_per_step")


def nnls(a, b):
    """Non-negative least squares min |a x - b|, x >= 0 (Lawson-Hanson active set)."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    n = a.shape[1]
    x, passive = np.zeros(n), np.zeros(n, bool)
    for _ in range(3 * n + 10):
        w = a.T @ (b - a @ x)
        free = ~passive & (w > 1e-12 * max(1.0, np.abs(w).max()))
        if not free.any():
            break
        passive[np.argmax(np.where(free, w, -np.inf))] = True
        while True:
            z = np.zeros(n)
            z[passive] = np.linalg.lstsq(a[:, passive], b, rcond=None)[0]
            if (z[passive] > 0).all():
                x = z
                break
            neg = passive & (z <= 0)
            alpha = np.min(x[neg] / (x[neg] - z[neg]))
            x = x + alpha * (z - x)
            passive &= x > 1e-15
    return x


def dims_create(p, n=(1, 1, 1)):
    """A near-cubic process grid of p ranks over a lattice n (the longest axis split first, as
    MPI_Dims_create on equal axes): the split that minimises the block surface."""
    best = None
    for a in range(1, p + 1):
        if p % a:
            continue
        for b in range(1, p // a + 1):
            if (p // a) % b:
                continue
            d = (a, b, p // a // b)
            blk = [n[i] / d[i] for i in range(3)]
            surf = blk[0] * blk[1] + blk[1] * blk[2] + blk[0] * blk[2]
            if best is None or surf < best[0] - 1e-9:
                best = (surf, d)
    return best[1]


def halo_values(block, dims):
    """(values, messages) a rank of `block` cells in a `dims` grid sends per step: D3Q19 links
    that cross to another rank, as fluid_app/parallel/halo_exchange.cpp lists them. A face of
    sides (m, k) carries m k + 2 (m - 1) k + 2 m (k - 1) = 5 m k - 2 m - 2 k links, an edge of
    length l carries l; a direction whose neighbour is the rank itself (one rank on a periodic
    axis) is a local copy, not counted. Periodic axes: every neighbour exists."""
    values, messages = 0, 0
    for e in [(x, y, z) for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1)]:
        nz = [i for i in range(3) if e[i]]
        if len(nz) not in (1, 2):
            continue
        if not any(dims[i] > 1 for i in nz):
            continue  # the neighbour is this rank (periodic) or absent
        other = [block[i] for i in range(3) if not e[i]]
        if len(nz) == 1:
            m, k = other
            values += 5 * m * k - 2 * m - 2 * k
        else:
            values += other[0]
        messages += 1
    return values, messages


def grown_volume(block, r):
    """Volume of a box grown by a ball of radius r (Steiner: V + S r + pi r^2 sum(edges)/4 ... for
    a box: V + 2 r (ab + bc + ca) + pi r^2 (a + b + c) + 4/3 pi r^3)."""
    a, b, c = block
    return (a * b * c + 2 * r * (a * b + b * c + c * a) + math.pi * r * r * (a + b + c)
            + 4.0 / 3.0 * math.pi * r ** 3)


def uniform_counters(cells, bodies, fluid_ranks, dem_ranks, per_body, reach, touch, ghost_reach,
                     spheres, precision_bytes=8):
    """Counters of the busiest fluid rank and DEM rank of a uniform suspension of `bodies` in a
    periodic cube of `cells` per side on a regular grid of ranks. per_body: covered, band and
    interior cells per body (measured); reach / touch: a body's reach in cells (bounding radius
    plus the coupling margin) and its bounding radius; ghost_reach: the DEM ghost shell in cells
    (measured); spheres: clump spheres per body."""
    n = (cells, cells, cells)
    d = dims_create(fluid_ranks, n)
    block = [math.ceil(n[i] / d[i]) for i in range(3)]
    density = bodies / float(cells) ** 3
    c = float(np.prod(block))
    f = {"cells": c,
         "cells_with_ghosts": float(np.prod([b + 2 for b in block])),
         "porous_row_cells": c * porous_row_fraction(density, block[0], per_body["covered"]),
         "covered_cells": per_body["covered"] * density * c,
         "band_cells": per_body["band"] * density * c,
         "body_interior_cells": per_body["interior"] * density * c,
         "bodies_in_table": min(bodies, density * grown_volume(block, reach)),
         "bodies_touching": min(bodies, density * grown_volume(block, touch))}
    values, messages = halo_values(block, d)
    f["halo_bytes_per_step"] = float(values * precision_bytes)
    f["halo_messages_per_step"] = float(messages)
    f["coupler_bytes_per_step"] = f["bodies_in_table"] * (STATE_BYTES + LOAD_BYTES)
    dd = dims_create(dem_ranks, n)
    dblock = [n[i] / dd[i] for i in range(3)]
    atoms = spheres * bodies / dem_ranks
    ghosts = spheres * density * (grown_volume(dblock, ghost_reach) - np.prod(dblock))
    owned = bodies / dem_ranks
    # Each body's state goes to every fluid rank it reaches and a load comes back from each.
    reached = fluid_ranks * f["bodies_in_table"] / bodies
    dem = {"bodies_owned": owned, "atoms": atoms, "ghost_atoms": ghosts,
           "coupler_bytes_per_step": (STATE_BYTES + LOAD_BYTES) * owned * reached}
    return {"fluid": f, "dem": dem, "fluid_dims": d, "dem_dims": dd}


def porous_row_fraction(density, row, covered):
    """Fraction of the rows of `row` cells along x that a suspension of randomly placed and
    oriented bodies covers, `density` bodies per cell, each covering `covered` cells (band and
    interior). A row meets a body when the body's covered region meets the segment: the
    Minkowski sum of a segment of length L and a convex body of volume V and mean projected
    area A is A L + V (Cauchy: A = S / 4 for random orientations; the region taken as a cube of
    volume V, A = 1.5 V^(2/3)); with Poisson-placed bodies, a row escapes all of them with
    probability exp(-density (A L + V))."""
    area = 1.5 * covered ** (2.0 / 3.0)
    return 1.0 - math.exp(-density * (area * row + covered))


def ghost_reach_from(atoms, ghosts, box):
    """The DEM ghost shell (cells) that gives `ghosts` ghost atoms around a periodic box of
    `box` cells holding `atoms` atoms on one rank: solves grown_volume(box, r) = V (1 + g / a)."""
    target = float(np.prod(box)) * (1.0 + ghosts / max(atoms, 1.0))
    lo, hi = 0.0, float(max(box))
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if grown_volume(box, mid) < target else (lo, mid)
    return 0.5 * (lo + hi)


class Model:
    """Per-unit costs (seconds) and memory (bytes) of the coupled step."""

    def __init__(self, costs=None, memory=None):
        self.costs = dict(costs or {})
        self.memory = dict(memory or {})

    def lattice(self, f):
        """The lattice part of a fluid rank's busy time, without the halo."""
        c = self.costs
        # A model fitted before the porous-row counter has no c_row (and needs no counter).
        rows = c["porous_row"] * f["porous_row_cells"] if "porous_row" in c else 0.0
        return c["cell"] * f["cells"] + rows + c["covered"] * f["covered_cells"]

    def porosity(self, f):
        """The porosity + momentum exchange part of a fluid rank's busy time."""
        c = self.costs
        return c["porosity_cell"] * f["covered_cells"] + c["body"] * f["bodies_in_table"]

    def fluid_busy(self, f):
        return (self.lattice(f) + self.porosity(f)
                + self.costs.get("halo_byte", 0.0) * f["halo_bytes_per_step"])

    def exchange(self, side):
        return self.costs["exchange_step"] + self.costs["coupler_byte"] * side[
            "coupler_bytes_per_step"]

    def dem_busy(self, d, substeps):
        return self.costs["dem_step"] + self.costs["atom_substep"] * (
            d["atoms"] + d["ghost_atoms"]) * substeps

    def step(self, fluid_ranks, dem_ranks, substeps):
        """Predicted time per coupled step from lists of per-rank counter dicts."""
        f = max(self.fluid_busy(r) + self.exchange(r) for r in fluid_ranks)
        d = max(self.dem_busy(r, substeps) + self.exchange(r) for r in dem_ranks)
        return max(f, d), f, d

    def calibrated(self, fluid_ranks, busy):
        """(factor, model): the fluid per-unit costs scaled by one factor so that the busiest
        of `fluid_ranks` (counter dicts of one measured run) costs `busy` seconds per step, the
        exchange and DEM costs kept. Carries what the fit scenes do not show (randomly
        oriented cubes, fluid ranks streaming their populations at once) from one measured
        run of a large system to others."""
        factor = busy / max(self.fluid_busy(r) for r in fluid_ranks)
        costs = dict(self.costs)
        for k in FLUID_COSTS:
            if k in costs:
                costs[k] *= factor
        return factor, Model(costs, self.memory)

    def fluid_memory(self, f):
        m = self.memory
        return m["fluid_base"] + m["fluid_cell"] * f["cells_with_ghosts"]

    def dem_memory(self, d, bodies):
        m = self.memory
        return (m["dem_base"] + m["dem_body_global"] * bodies
                + m["dem_atom"] * (d["atoms"] + d["ghost_atoms"]))


def fit_costs(runs, halo_runs=()):
    """Costs from 1-rank runs. Each run: dict with the fluid counters `f` (one rank), the rank-0
    parts `lattice`, `porosity`, `exchange` (s per step), the DEM counters `d`, `dem` (s per
    step), `substeps`, and `rotated` (randomly oriented bodies: the porosity costs come from
    these runs where there are any). halo_runs: (per-rank fluid counters, per-rank busy s) of a run on more
    fluid ranks, for c_halo (the one cost a single rank cannot show)."""
    lat = nnls([[r["f"]["cells"], r["f"]["porous_row_cells"], r["f"]["covered_cells"]]
                for r in runs], [r["lattice"] for r in runs])
    turned = [r for r in runs if r.get("rotated")] or runs
    por = nnls([[r["f"]["covered_cells"], r["f"]["bodies_in_table"]] for r in turned],
               [r["porosity"] for r in turned])
    xb = nnls([[1.0, r["f"]["coupler_bytes_per_step"]] for r in runs],
              [r["exchange"] for r in runs])
    dem = nnls([[1.0, (r["d"]["atoms"] + r["d"]["ghost_atoms"]) * r["substeps"]] for r in runs],
               [r["dem"] for r in runs])
    m = Model({"cell": lat[0], "porous_row": lat[1], "covered": lat[2], "porosity_cell": por[0],
               "body": por[1],
               "exchange_step": xb[0], "coupler_byte": xb[1],
               "dem_step": dem[0], "atom_substep": dem[1]})
    rows, rhs = [], []
    for ranks, busy in halo_runs:
        for f, b in zip(ranks, busy):
            rows.append([f["halo_bytes_per_step"]])
            rhs.append(b - m.fluid_busy(dict(f, halo_bytes_per_step=0.0)))
    m.costs["halo_byte"] = float(nnls(rows, rhs)[0]) if rows else 0.0
    return m


def fit_memory(fluid_ranks, dem_ranks, global_body_bytes):
    """Memory per rank (bytes) from measured max RSS: fluid base + per cell (with the ghost
    layer); DEM base + global tables per body (global_body_bytes, from the structure sizes) +
    per local and ghost atom. fluid_ranks: (counters, rss bytes); dem_ranks: (counters, bodies,
    rss bytes)."""
    fa = np.array([[1.0, f["cells_with_ghosts"]] for f, _ in fluid_ranks])
    fb = np.array([rss for _, rss in fluid_ranks])
    fm = nnls(fa, fb)
    da = np.array([[1.0, d["atoms"] + d["ghost_atoms"]] for d, _, _ in dem_ranks])
    db = np.array([rss - global_body_bytes * n for _, n, rss in dem_ranks])
    dm = nnls(da, db)
    return {"fluid_base": fm[0], "fluid_cell": fm[1], "dem_base": dm[0],
            "dem_body_global": float(global_body_bytes), "dem_atom": dm[1]}
