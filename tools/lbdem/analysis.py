"""Analysis of a settling run (docs/study.md, "Analysis"): steady state, settling velocity in the
zero-volume-flux frame with a block-averaged error bar, g(r), C(r) of delta v_z, VACF of v_xy, and
orientation statistics of cubes. Functions take plain arrays: positions (T, N, 3), velocities
(T, N, 3), quaternions (T, N, 4), box edges (3,)."""
import numpy as np

from . import geometry


def mser_start(x, batch=5):
    """Start of the steady state of a series by MSER-5 (White 1997; Franklin & White 2008): the
    truncation d (a multiple of `batch` samples, at most half the batches) that minimises the
    squared standard error of the mean of what remains, var(x[d:]) / (n - d). Returns the index."""
    x = np.asarray(x, float)
    nb = len(x) // batch
    if nb < 4:
        return 0
    means = x[: nb * batch].reshape(nb, batch).mean(axis=1)
    best, best_d = np.inf, 0
    for d in range(nb // 2 + 1):
        rest = means[d:]
        score = rest.var() / len(rest)
        if score < best:
            best, best_d = score, d
    return best_d * batch


def block_average(x, min_blocks=8):
    """Mean of a correlated series and its standard error by blocking (Flyvbjerg & Petersen 1989):
    the standard error of the block means is computed for blocks of 1, 2, 4, ... samples; it
    rises with the block size until blocks are longer than the correlation time and then levels
    off. Returns (mean, error), the error being the largest estimate with >= min_blocks blocks."""
    x = np.asarray(x, float)
    mean = x.mean()
    err = x.std(ddof=1) / np.sqrt(len(x)) if len(x) > 1 else np.nan
    y = x
    while len(y) // 2 >= min_blocks:
        y = 0.5 * (y[: len(y) // 2 * 2 : 2] + y[1 : len(y) // 2 * 2 : 2])
        err = max(err, y.std(ddof=1) / np.sqrt(len(y)))
    return mean, err


def settling_velocity(up_z, j_z):
    """Mean body velocity in the zero-volume-flux frame, V = <u_p,z> - j_z (signed: negative for
    bodies settling along -z).

    j is the volume flux phi <u_p> + (1 - phi) <u_f> (a zero-volume-flux frame is the frame where
    j = 0: a closed container, Richardson & Zaki 1954). The fluid series' mean_uz averages the
    lattice velocity over ALL nodes, and inside a body the HLBM velocity is the body's, so
    mean_uz is j itself (not <u_f>): V = <u_p> - mean_uz. Adding phi <u_p> to mean_uz again (as
    an earlier plot did) counts the bodies twice and gives (1 - phi)(<u_p> - j)."""
    return np.asarray(up_z, float) - np.asarray(j_z, float)


def momentum_change(fluid, bodies, applied):
    """Change of the momentum of fluid plus bodies less the impulse of the external forces since
    the first row: (fluid + bodies - applied)(t) - (fluid + bodies - applied)(t_0), arrays
    (T, 3) in N s (the columns of fluid_app's momentum audit, docs/method-loads.md section 7).

    This, not the volume flux, is what a triply periodic settling box holds: with rho_p != rho_f
    the frame of zero momentum, rho_f (1 - phi) <u_f> + rho_p phi <u_p> = 0, has the volume flux
    j = phi <u_p> (1 - rho_p / rho_f) != 0."""
    total = np.asarray(fluid, float) + np.asarray(bodies, float) - np.asarray(applied, float)
    return total - total[0]


def verlet_orbital_gain(x, v, mass, box):
    """Angular momentum (T, 3), summed over bodies and from the first row on, that the DEM's
    velocity Verlet adds to the bodies' orbital part sum (x - c) x m v beyond the moment of the
    loads' impulse, from positions x and velocities v (T, N, 3) at every fluid step, masses (N,)
    and the periodic box lengths (3,) (minimum image of the moves).

    Under a load F constant over the step Verlet moves a body exactly along
    x(t) = x^n + v^n t + F t^2 / (2 m) (its substeps too), so
    (x^{n+1} - c) x m v^{n+1} - (x^n - c) x m v^n = (x^n - c) x F dt + (x^{n+1} - x^n) x m v^{n+1}:
    the first term is the moment of the impulse the fluid gave up (about c, at x^n), the second,
    dt^2 / 2 v^n x F, is the integrator's own (docs/method-loads.md section 7). Exact without
    contacts (a contact force varies within the step)."""
    x, v = np.asarray(x, float), np.asarray(v, float)
    box = np.asarray(box, float)
    moved = np.diff(x, axis=0)
    moved -= box * np.round(moved / box)
    per_step = np.cross(moved, np.asarray(mass, float)[None, :, None] * v[1:]).sum(axis=1)
    return np.vstack([np.zeros(3), np.cumsum(per_step, axis=0)])


def fit_hindered_settling(phi, u, err=None):
    """Least-squares fit of u = k (1 - phi)^n (u: u/u_T at solid fractions phi), as a straight
    line ln u = ln k + n ln(1 - phi), weighted by the relative errors err / u when given. Returns
    {k, n, k_error, n_error, rms_relative_residual}; the errors are the fit's standard errors:
    from the given errors, scaled up by the residual scatter where that is larger (chi^2 per
    degree of freedom above 1); without errors from the scatter alone (NaN with two points)."""
    phi, u = np.asarray(phi, float), np.asarray(u, float)
    x, y = np.log1p(-phi), np.log(u)
    w = np.ones_like(x) if err is None else (u / np.maximum(np.asarray(err, float), 1e-12))
    a = np.vstack([np.ones_like(x), x]).T * w[:, None]
    coef, *_ = np.linalg.lstsq(a, y * w, rcond=None)
    resid = y - (coef[0] + coef[1] * x)
    dof = len(x) - 2
    if dof > 0 or err is not None:
        chi2 = float(np.sum((w * resid) ** 2) / dof) if dof > 0 else 0.0
        s2 = chi2 if err is None else max(1.0, chi2)
        cov = s2 * np.linalg.inv(a.T @ a)
        ln_k_err, n_err = float(np.sqrt(cov[0, 0])), float(np.sqrt(cov[1, 1]))
    else:
        ln_k_err = n_err = float("nan")
    k = float(np.exp(coef[0]))
    return {"k": k, "n": float(coef[1]), "k_error": k * ln_k_err, "n_error": n_err,
            "rms_relative_residual": float(np.sqrt(np.mean(np.expm1(resid) ** 2)))}


def slip_velocity(v_zero_flux, phi):
    """Relative velocity of bodies and fluid, <u_p> - <u_f> = V / (1 - phi), from the settling
    velocity V in the zero-volume-flux frame (j = phi u_p + (1 - phi) u_f = 0)."""
    return np.asarray(v_zero_flux, float) / (1.0 - phi)


def curve_difference(t, u, t_ref, u_ref, max_shift=0.1, shift_steps=81):
    """How far a computed u(t) lies from a reference curve (e.g. a digitized experiment), in
    units of the reference's peak |u_ref|: the RMS and the largest difference at the reference's
    points that lie inside the computed time span (u interpolated linearly there), as given and
    with the reference's time origin moved by the shift in [-max_shift, max_shift] that makes
    the RMS smallest (a digitized figure's time origin is uncertain by tens of ms).

    Returns a dict: n (points compared), rms, largest, t_largest, shift, rms_shifted."""
    t, u = np.asarray(t, float), np.asarray(u, float)
    t_ref, u_ref = np.asarray(t_ref, float), np.asarray(u_ref, float)
    peak = np.max(np.abs(u_ref))

    def compare(shift):
        tr = t_ref + shift
        inside = (tr >= t[0]) & (tr <= t[-1])
        if inside.sum() < 2:
            return None
        d = (np.interp(tr[inside], t, u) - u_ref[inside]) / peak
        return d, tr[inside]

    at_zero = compare(0.0)
    if at_zero is None:
        raise ValueError("the reference curve and the run share fewer than two time points")
    d, tr = at_zero
    k = int(np.argmax(np.abs(d)))
    rms = {}
    for s in np.linspace(-max_shift, max_shift, shift_steps):
        c = compare(s)
        if c is not None:
            rms[float(s)] = float(np.sqrt(np.mean(c[0] ** 2)))
    best = min(rms, key=rms.get)
    return {"n": len(d), "rms": float(np.sqrt(np.mean(d**2))), "largest": float(d[k]),
            "t_largest": float(tr[k]), "shift": best, "rms_shifted": rms[best]}


def smoothed_peak(t, u, period):
    """The largest value of u(t) after a centred moving average over one `period` (seconds).

    A body's speed ripples at its lattice-crossing frequency (the nearest-voxel lookup changes
    the covered cells each time it moves by one cell dx, period dx / u); the raw maximum takes
    the crest of that ripple, not the speed. Each sample is replaced by the mean of the samples
    within +- period / 2 of it (the window is cut at the ends of the run, where fewer samples
    enter). Returns (index, t at the peak, smoothed peak, smoothed series, samples per window);
    with fewer than two samples per period the series is returned as it is."""
    t, u = np.asarray(t, float), np.asarray(u, float)
    if len(t) == 0:
        raise ValueError("smoothed_peak: empty series")
    half = 0.5 * period
    lo = np.searchsorted(t, t - half, side="left")
    hi = np.searchsorted(t, t + half, side="right")
    counts = hi - lo
    if not np.isfinite(period) or period <= 0 or np.median(counts) < 2:
        smooth, n = u.copy(), 1
    else:
        c = np.concatenate(([0.0], np.cumsum(u)))
        smooth, n = (c[hi] - c[lo]) / counts, int(np.median(counts))
    k = int(np.argmax(smooth))
    return k, float(t[k]), float(smooth[k]), smooth, n


def judge_known_off(signed_error, tolerance, band):
    """A case known to be off: passes only while its signed relative error stays outside the
    tolerance and inside the band (low, high) it was recorded in. Returns (ok, verdict)."""
    low, high = band
    if abs(signed_error) <= tolerance:
        return False, (f"now within the tolerance {100 * tolerance:.2f} %: the case is no longer "
                       "off, remove its known-off mark and give it a tolerance")
    if not low <= signed_error <= high:
        return False, (f"outside its recorded band [{100 * low:+.2f}, {100 * high:+.2f}] %: the "
                       "case changed, explain the new number before recording it")
    return True, (f"known off: {100 * signed_error:+.2f} % (tolerance {100 * tolerance:.2f} %, "
                  f"recorded band [{100 * low:+.2f}, {100 * high:+.2f}] %)")


def radial_distribution(positions, box, r_max=None, bins=50):
    """g(r) as in the paper: <N_pairs(r, r + dr)> / (N (N - 1) / 2 * shell volume / V), averaged
    over configurations, periodic minimum image (r_max <= L_min / 2). The exact shell volume
    4/3 pi ((r + dr)^3 - r^3) replaces 4 pi r^2 dr. Returns (bin centres, g)."""
    positions = np.asarray(positions, float)
    if positions.ndim == 2:
        positions = positions[None]
    box = np.asarray(box, float)
    r_max = r_max or 0.5 * box.min()
    edges = np.linspace(0, r_max, bins + 1)
    n = positions.shape[1]
    counts = np.zeros(bins)
    for x in positions:
        d = geometry.pair_separations(x, box)[2]
        counts += np.histogram(np.linalg.norm(d, axis=-1), bins=edges)[0]
    shell = 4.0 / 3.0 * np.pi * (edges[1:] ** 3 - edges[:-1] ** 3)
    ideal = 0.5 * n * (n - 1) * shell / np.prod(box)
    return 0.5 * (edges[1:] + edges[:-1]), counts / (len(positions) * ideal)


def near_pair_series(positions, box, r_near):
    """Per snapshot, the mean of g(r) over r < r_near: pairs closer than r_near over the
    ideal-gas count N (N - 1) / 2 * (4/3 pi r_near^3) / V (minimum image, r_near <= L_min / 2).
    A scalar of the near structure whose steady start (mser_start) says when g(r) has stopped
    changing. Returns an array (T,)."""
    positions = np.asarray(positions, float)
    if positions.ndim == 2:
        positions = positions[None]
    box = np.asarray(box, float)
    n = positions.shape[1]
    ideal = 0.5 * n * (n - 1) * 4.0 / 3.0 * np.pi * r_near**3 / np.prod(box)
    out = np.empty(len(positions))
    for t, x in enumerate(positions):
        d = geometry.pair_separations(x, box)[2]
        out[t] = np.count_nonzero(np.einsum("pi,pi->p", d, d) < r_near * r_near) / ideal
    return out


def velocity_correlation(positions, vz, box, r_max=None, bins=20):
    """C(r) = <dv_z(0) dv_z(r)> / <dv_z^2> over pairs at distance r (the paper), dv_z = v_z minus
    the mean over bodies at that time, up to L/2 (minimum image). Returns (bin centres, C);
    bins without pairs give nan."""
    positions = np.asarray(positions, float)
    vz = np.asarray(vz, float)
    if positions.ndim == 2:
        positions, vz = positions[None], vz[None]
    box = np.asarray(box, float)
    r_max = r_max or 0.5 * box.min()
    edges = np.linspace(0, r_max, bins + 1)
    prod = np.zeros(bins)
    count = np.zeros(bins)
    var = 0.0
    for x, v in zip(positions, vz):
        dv = v - v.mean()
        var += np.mean(dv * dv)
        i, j, d = geometry.pair_separations(x, box)
        r = np.linalg.norm(d, axis=-1)
        k = np.digitize(r, edges) - 1
        ok = (k >= 0) & (k < bins)
        prod += np.bincount(k[ok], weights=(dv[i] * dv[j])[ok], minlength=bins)
        count += np.bincount(k[ok], minlength=bins)
    var /= len(positions)
    with np.errstate(invalid="ignore", divide="ignore"):
        c = prod / count / var
    return 0.5 * (edges[1:] + edges[:-1]), c


def vacf(v, max_lag=None, subtract_mean=True):
    """C(t) = <v(t0 + t) . v(t0)> / <v(t0)^2> over bodies and time origins t0 (the paper, for the
    horizontal components: pass v (T, N, 2) = (v_x, v_y)). With subtract_mean the body-mean
    velocity at each time is removed first (the slow horizontal drift of the whole suspension the
    paper notes). Returns C at lags 0 .. max_lag (in output intervals)."""
    v = np.asarray(v, float)
    if subtract_mean:
        v = v - v.mean(axis=1, keepdims=True)
    t = v.shape[0]
    max_lag = t // 2 if max_lag is None else min(max_lag, t - 1)
    c = np.array([np.mean(np.sum(v[lag:] * v[: t - lag], axis=-1)) for lag in range(max_lag + 1)])
    return c / c[0]


def axes_against_gravity(q, gravity=(0.0, 0.0, -1.0)):
    """|cos| of the angle between each body axis and gravity: (..., 3) from quaternions (..., 4).
    For uniformly random orientations each is uniform on [0, 1] (mean 1/2); a cube falling
    face-down has one axis at 1 and two at 0."""
    g = np.asarray(gravity, float)
    g = g / np.linalg.norm(g)
    r = geometry.rotation_matrices(q)
    return np.abs(np.einsum("...ik,i->...k", r, g))


def contact_face_angles(positions, q, box, edge, gap):
    """Angles (degrees) between the most nearly parallel faces of cube pairs closer than `gap`
    (separating-axis lower bound of the distance between the cubes): min over the 3 x 3 pairs of
    face normals of arccos |n_a . n_b|. 0 means a face-parallel contact; for independent random
    orientations the angle is spread over 0 - 54.7 degrees. Returns a 1-d array over all
    configurations."""
    positions = np.asarray(positions, float)
    q = np.asarray(q, float)
    if positions.ndim == 2:
        positions, q = positions[None], q[None]
    half = np.full(3, 0.5 * edge)
    out = []
    for x, qq in zip(positions, q):
        i, j, d = geometry.pair_separations(x, box)
        near = np.linalg.norm(d, axis=-1) < np.sqrt(3) * edge + gap
        i, j, d = i[near], j[near], d[near]
        if len(i) == 0:
            continue
        r = geometry.rotation_matrices(qq)
        sep = geometry.box_separation(d, r[i], r[j], half, half)
        touch = sep < gap
        ra, rb = r[i[touch]], r[j[touch]]
        cos = np.abs(np.einsum("mik,mil->mkl", ra, rb)).reshape(-1, 9).max(axis=1)
        out.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
    return np.concatenate(out) if out else np.zeros(0)
