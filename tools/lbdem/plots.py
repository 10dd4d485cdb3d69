"""The study's figures, in the paper's style: u/u_T against phi with Richardson-Zaki, Batchelor,
Yin & Koch's fit and the study's own fit per shape, g(r), C(r) of delta v_z, and the VACF of v_xy
(one PNG each)."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import references  # noqa: E402

MARKERS = {"sphere": ("o", "tab:blue"), "cube": ("s", "tab:red")}


def settling_plot(rows, reynolds, path, fits=None):
    fig, ax = plt.subplots(figsize=(5.5, 4))
    phi = np.linspace(0.0, 0.45, 100)
    ax.plot(phi, references.richardson_zaki(phi, reynolds), "k-",
            label=f"Richardson-Zaki, Re = {reynolds:g} "
                  f"(n = {references.richardson_zaki_exponent(reynolds):.2f})")
    ax.plot(phi[phi < 0.1], references.batchelor(phi[phi < 0.1]), "k--",
            label="Batchelor, 1 - 6.55 phi")
    k_yk, n_yk = references.yin_koch_fit(reynolds)
    ax.plot(phi, references.yin_koch(phi, reynolds), "k-.",
            label=f"Yin & Koch 2007 fit, Re = {reynolds:g} (k = {k_yk:.2f}, n = {n_yk:.2f})")
    # Their two fits that bracket the study's Reynolds number, as they published them.
    for re_t, k, n in references.yin_koch_bracket(reynolds):
        ax.plot(phi, k * (1 - phi) ** n, "-.", color="grey", lw=0.7,
                label=f"Yin & Koch 2007 fit at their Re_t = {re_t:g} (k = {k:.2f}, n = {n:.1f})")
    for shape in ("sphere", "cube"):
        sel = [r for r in rows if r["shape"] == shape]
        if not sel:
            continue
        m, c = MARKERS[shape]
        ax.errorbar([r["phi"] for r in sel], [r["u_over_uT"] for r in sel],
                    yerr=[r["u_over_uT_error"] for r in sel], fmt=m, color=c, capsize=3,
                    label=f"{shape}s (u_T = {sel[0]['u_T']:.4g} m/s, this code)")
        if fits and shape in fits:
            f = fits[shape]
            ax.plot(phi, f["k"] * (1 - phi) ** f["n"], ":", color=c,
                    label=f"fit to the {shape}s: k = {f['k']:.2f}, n = {f['n']:.2f}")
    ax.set_xlabel(r"solid fraction $\phi$")
    ax.set_ylabel(r"$\langle u \rangle / u_T$ (zero-volume-flux frame)")
    ax.set_xlim(0, 0.45)
    ax.set_ylim(0, 1.05)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def per_shape_plot(rows, curves, path, x_key, y_key, xlabel, ylabel, scale, marks=None):
    shapes = [s for s in ("sphere", "cube") if any(r["shape"] == s for r in rows)]
    fig, axes = plt.subplots(len(shapes), 1, figsize=(5.5, 3.2 * len(shapes)), squeeze=False)
    for ax, shape in zip(axes[:, 0], shapes):
        for r in rows:
            if r["shape"] != shape:
                continue
            cv = curves[(shape, r["phi_nominal"])]
            ax.plot(cv[x_key] / scale(r), cv[y_key], "-", label=f"phi = {r['phi']:.3f}")
        if marks and shape in marks:
            ax.axvline(marks[shape], color="k", ls="--", lw=0.8)
        ax.set_title(shape + "s", fontsize=9)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def relaxation_plot(rows, curves, d, near_pairs, path):
    """Per run, the settling speed u/u_T and the mean g(r) below near_pairs d against t u_T / d,
    with the steady start (the later of the two MSER starts) marked: how long a run must be."""
    shapes = [s for s in ("sphere", "cube") if any(r["shape"] == s for r in rows)]
    fig, axes = plt.subplots(2, len(shapes), figsize=(5 * len(shapes), 6), squeeze=False)
    for col, shape in enumerate(shapes):
        for r in (r for r in rows if r["shape"] == shape):
            cv = curves[(shape, r["phi_nominal"])]
            t = cv["time"] * r["u_T"] / d
            line, = axes[0, col].plot(t, cv["speed"] / r["u_T"], lw=0.8,
                                      label=f"phi = {r['phi']:.3f}")
            axes[1, col].plot(t, cv["near"], lw=0.8, color=line.get_color())
            for ax in axes[:, col]:
                ax.axvline(r["t_steady"] * r["u_T"] / d, color=line.get_color(), ls="--", lw=0.8)
        axes[0, col].set_title(shape + "s", fontsize=9)
        axes[0, col].set_ylabel(r"$u / u_T$")
        axes[1, col].set_ylabel(rf"mean $g(r)$, $r < {near_pairs:g}\,d$")
        axes[1, col].set_xlabel(r"$t\,u_T / d$")
        axes[0, col].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def study_plots(rows, curves, out, reynolds, d, a, fits=None, near_pairs=1.5):
    paths = [os.path.join(out, n) for n in ("settling.png", "rdf.png", "correlation.png",
                                            "vacf.png", "relaxation.png")]
    settling_plot(rows, reynolds, paths[0], fits)
    per_shape_plot(rows, curves, paths[1], "r", "g", r"$r / d$", r"$g(r)$", lambda r: d,
                   marks={"cube": a / d})
    per_shape_plot(rows, curves, paths[2], "rc", "C", r"$r / L$", r"$C(r)$ of $\delta v_z$",
                   lambda r: r["box_cells"] * d / r["cells_per_diameter"])
    per_shape_plot(rows, curves, paths[3], "lag", "vacf", r"$t\,u_T / d$",
                   r"VACF of $v_{xy}$", lambda r: d / r["u_T"])
    relaxation_plot(rows, curves, d, near_pairs, paths[4])
    return paths


def speed_history_plot(t, u, label, curves, peak_reference, path):
    """A body's settling speed against time with measured curves (name -> (t, u)) and the
    reference peak as a horizontal line."""
    fig, ax = plt.subplots(figsize=(5.5, 4))
    ax.plot(t, u, "k-", label=f"this code, {label}")
    for (name, (t_ref, u_ref)), m in zip(curves.items(), ("o", "s", "^")):
        ax.plot(t_ref, u_ref, m, mfc="none", label=name)
    ax.axhline(peak_reference, color="grey", ls=":", label=f"peak, Table II ({peak_reference:g})")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("settling speed (m/s)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)
