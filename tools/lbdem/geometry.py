"""Rotations, periodic distances and the overlap test of two cubes (boxes), vectorised."""
import numpy as np


def rotation_matrices(q):
    """Rotation matrices (..., 3, 3) of quaternions (..., 4) = (w, x, y, z), shape frame -> space.
    Column k is body axis k in space."""
    q = np.asarray(q, float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = (q[..., i] for i in range(4))
    r = np.empty(q.shape[:-1] + (3, 3))
    r[..., 0, 0] = 1 - 2 * (y * y + z * z)
    r[..., 0, 1] = 2 * (x * y - w * z)
    r[..., 0, 2] = 2 * (x * z + w * y)
    r[..., 1, 0] = 2 * (x * y + w * z)
    r[..., 1, 1] = 1 - 2 * (x * x + z * z)
    r[..., 1, 2] = 2 * (y * z - w * x)
    r[..., 2, 0] = 2 * (x * z - w * y)
    r[..., 2, 1] = 2 * (y * z + w * x)
    r[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return r


def random_quaternions(rng, n):
    """Uniformly distributed rotations (Shoemake, Graphics Gems III), as (n, 4) (w, x, y, z)."""
    u1, u2, u3 = rng.random(n), rng.random(n), rng.random(n)
    a, b = np.sqrt(1 - u1), np.sqrt(u1)
    return np.stack([b * np.cos(2 * np.pi * u3), a * np.sin(2 * np.pi * u2),
                     a * np.cos(2 * np.pi * u2), b * np.sin(2 * np.pi * u3)], axis=-1)


def quaternion_multiply(p, q):
    pw, px, py, pz = (p[..., i] for i in range(4))
    qw, qx, qy, qz = (q[..., i] for i in range(4))
    return np.stack([pw * qw - px * qx - py * qy - pz * qz, pw * qx + px * qw + py * qz - pz * qy,
                     pw * qy - px * qz + py * qw + pz * qx, pw * qz + px * qy - py * qx + pz * qw],
                    axis=-1)


def minimum_image(d, box):
    """Separation vectors d (..., 3) folded to the nearest periodic image of a box (3,)."""
    box = np.asarray(box, float)
    return d - box * np.round(d / box)


def pair_separations(x, box):
    """Upper-triangle pair vectors (i < j) of positions x (N, 3) with the minimum image:
    returns (i, j, d) with d (P, 3) = x_j - x_i folded."""
    i, j = np.triu_indices(len(x), k=1)
    return i, j, minimum_image(x[j] - x[i], box)


def box_separation(t, ra, rb, ha, hb):
    """Separating-axis test of boxes (Gottschalk et al. 1996, "OBBTree"): centre offsets t (M, 3),
    axes ra, rb (M, 3, 3) (columns), half extents ha, hb (3,). Returns (M,) the largest gap over
    the 15 candidate axes: > 0 means the boxes do not overlap (and is a lower bound of their
    distance), <= 0 means they overlap."""
    t = np.atleast_2d(t)
    a = np.swapaxes(ra, -1, -2)  # rows: the axes of box a in space
    b = np.swapaxes(rb, -1, -2)
    m = t.shape[0]
    cross = np.cross(a[:, :, None, :], b[:, None, :, :]).reshape(m, 9, 3)
    axes = np.concatenate([a, b, cross], axis=1)  # (M, 15, 3)
    norm = np.linalg.norm(axes, axis=-1)
    ok = norm > 1e-9  # parallel edges give a zero cross product: the face axes cover that case
    n = axes / np.where(ok, norm, 1.0)[..., None]
    proj_a = np.abs(np.einsum("mlj,mkj->mlk", n, a)) @ np.asarray(ha, float)
    proj_b = np.abs(np.einsum("mlj,mkj->mlk", n, b)) @ np.asarray(hb, float)
    gap = np.abs(np.einsum("mlj,mj->ml", n, t)) - proj_a - proj_b
    return np.where(ok, gap, -np.inf).max(axis=1)


# The nine edge-edge axes a_i x b_j of box_separated: component indices i+1, i+2 and j+1, j+2.
_I = np.repeat(np.arange(3), 3)
_J = np.tile(np.arange(3), 3)
_I1, _I2, _J1, _J2 = (_I + 1) % 3, (_I + 2) % 3, (_J + 1) % 3, (_J + 2) % 3


def boxes_separated(t, ra, rb, ha, hb, margin=0.0):
    """The separating-axis test in the form of Gottschalk et al. (1996), eqs. of their Table 1:
    the 15 axes written in the frame of box a (R = A^T B, t_a = A^T t), no normalisation. Centre
    offsets t (M, 3), axes ra, rb (M, 3, 3) (columns), half extents ha, hb (3,). Returns (M,)
    True where some axis separates the boxes by more than `margin` (a length). |R| + 1e-12 keeps
    the test conservative for parallel edges (a zero cross product never separates)."""
    r = np.einsum("mki,mkj->mij", ra, rb)
    ab = np.abs(r) + 1e-12
    ta = np.einsum("mki,mk->mi", ra, t)
    tb = np.einsum("mkj,mk->mj", rb, t)
    ha, hb = np.asarray(ha, float), np.asarray(hb, float)
    sep = (np.abs(ta) > ha + ab @ hb + margin).any(axis=1)
    sep |= (np.abs(tb) > np.einsum("mij,i->mj", ab, ha) + hb + margin).any(axis=1)
    # Axis a_i x b_j (length sin(a_i, b_j) <= 1, so a margin on the unnormalised projections is
    # at least `margin` along the unit axis).
    lhs = np.abs(ta[:, _I2] * r[:, _I1, _J] - ta[:, _I1] * r[:, _I2, _J])
    rhs = (ha[_I1] * ab[:, _I2, _J] + ha[_I2] * ab[:, _I1, _J]
           + hb[_J1] * ab[:, _I, _J2] + hb[_J2] * ab[:, _I, _J1])
    return sep | (lhs > rhs + margin).any(axis=1)
