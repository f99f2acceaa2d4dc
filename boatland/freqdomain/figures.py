"""Figures of the frequency-domain tools (matplotlib, imported lazily; Agg backend: files only).

Each ``figure_*`` returns the matplotlib Figure (tests read its labels); ``plot_*`` saves it.

- :func:`figure_raos`: free and hinged RAOs and the hinge-force transfer functions against the period;
- :func:`figure_limits`: a polar map of the limiting Hs over (relative direction, Tp), in the one polar
  orientation of :mod:`boatland.plotstyle` (bow up, 180° head seas at the top);
- :func:`figure_pile_comparison`: heave and pitch RAOs in the open sea and beside the pile;
- :func:`figure_shear_sweep`: the limiting Hs against the fender's shear stiffness.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

__all__ = ["plot_limits", "plot_raos", "plot_shear_sweep", "plot_pile_comparison", "figure_limits", "figure_raos",
           "figure_shear_sweep", "figure_pile_comparison"]


def _pyplot():
    from boatland.plotstyle import pyplot

    return pyplot()


def _save(fig, path, dpi=120) -> Path:
    from boatland.plotstyle import save_figure

    return save_figure(fig, path, dpi=dpi)


def plot_raos(omega, free, bow_free, hinged, forces, path: str | Path, *, title: str = "") -> Path:
    """Save :func:`figure_raos` to ``path``."""
    return _save(figure_raos(omega, free, bow_free, hinged, forces, title=title), path)


def figure_raos(omega, free, bow_free, hinged, forces, *, title: str = ""):
    """Three panels against the wave period T = 2π/ω (one direction).

    Parameters
    ----------
    omega : ndarray, shape (Nw,)
    free : ndarray of complex, shape (Nw, 6)
        Free RAO [m/m, rad/m].
    bow_free : ndarray of complex, shape (Nw, 3)
        Translation of the (first) fender point of the free vessel [m/m].
    hinged : ndarray of complex, shape (Nw, 6)
        Hinged RAO.
    forces : ndarray of complex, shape (Nw, 3)
        Hinge force on the vessel summed over the contacts, (normal, vertical, horizontal) [N/m].
    title : str
        The inputs (scenario, database, direction, push).
    """
    plt = _pyplot()
    T = 2 * np.pi / np.asarray(omega)
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5), constrained_layout=True)
    for k, name in ((2, "heave [m/m]"), (0, "surge [m/m]"), (1, "sway [m/m]")):
        ax[0].plot(T, np.abs(free[:, k]), label=f"free {name}")
    for k, name in ((2, "z"), (0, "x"), (1, "y")):
        ax[0].plot(T, np.abs(bow_free[:, k]), "--", label=f"free, fender point {name} [m/m]")
    ax[0].set_title("free vessel: translations")
    ax[0].set_ylabel("translation per wave amplitude [m/m]")
    for k, name in ((3, "roll"), (4, "pitch"), (5, "yaw")):
        ax[1].plot(T, np.degrees(np.abs(free[:, k])), label=f"free {name}")
        ax[1].plot(T, np.degrees(np.abs(hinged[:, k])), "--", label=f"hinged {name}")
    ax[1].set_title("rotations: free and hinged at the fender")
    ax[1].set_ylabel("rotation per wave amplitude [deg/m]")
    for k, name in enumerate(("normal", "vertical", "horizontal")):
        ax[2].plot(T, np.abs(forces[:, k]) / 1e3, label=name)
    ax[2].set_title("hinge force on the vessel (the most loaded contact)")
    ax[2].set_ylabel("force per wave amplitude [kN/m]")
    for a in ax:
        a.set_xlabel("wave period T [s]")
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    if title:
        fig.suptitle(title, fontsize=10)
    return fig


def plot_limits(table, path: str | Path, *, title: str = "") -> Path:
    """Save :func:`figure_limits` to ``path``."""
    return _save(figure_limits(table, title=title), path)


def figure_limits(table, *, title: str = ""):
    """Polar map of :class:`~boatland.freqdomain.statistics.LimitTable`: angle = relative wave direction
    (:mod:`boatland.plotstyle`: bow up, 180° head seas at the top, waves from starboard on the right),
    radius = Tp [s], colour = limiting Hs [m]. ``title``: the inputs (scenario, μ, push, ...)."""
    from boatland.plotstyle import POLAR_NOTE, heading_polar

    plt = _pyplot()
    beta = np.asarray(table.beta_deg, dtype=float)
    order = np.argsort(beta % 360)
    b = np.radians(beta[order] % 360)
    Hs = np.where(np.isfinite(table.Hs), table.Hs, np.nan)[:, order]
    # cell edges: midway between directions (periodic) and periods
    bb = np.concatenate([b, [b[0] + 2 * np.pi]])
    edges_b = np.concatenate([[b[0] - 0.5 * (bb[1] - bb[0]) if b.size > 1 else b[0] - np.pi],
                              0.5 * (bb[:-1] + bb[1:])]) if b.size > 1 else np.array([0, 2 * np.pi])
    T = np.asarray(table.Tp, dtype=float)
    edges_t = np.concatenate([[T[0] - 0.5 * (T[1] - T[0])], 0.5 * (T[:-1] + T[1:]), [T[-1] + 0.5 * (T[-1] - T[-2])]]) \
        if T.size > 1 else np.array([0.9 * T[0], 1.1 * T[0]])
    fig = plt.figure(figsize=(7, 6.8), layout="constrained")
    ax = fig.add_subplot(projection="polar")
    mesh = ax.pcolormesh(edges_b, edges_t, Hs, cmap="viridis", shading="flat")
    fig.colorbar(mesh, ax=ax, label="limiting Hs [m]", shrink=0.75, pad=0.1)
    ax.set_ylim(0, edges_t[-1])
    ax.set_rgrids(_few_ticks(edges_t[0], edges_t[-1]))
    heading_polar(ax, rlabel="Tp [s]")
    head = f"limiting Hs for P = {table.accept:g} per access ({table.statistics}, {table.method} hinge)"
    ax.set_title((f"{title}\n" if title else "") + f"{head}\nradius Tp [s]; {POLAR_NOTE}", fontsize=8)
    return fig


def _few_ticks(lo: float, hi: float) -> list[float]:
    """At most five round radial ticks in (lo, hi]: readable labels on a polar axis."""
    step = max(1.0, float(np.ceil((hi - max(lo, 0.0)) / 5.0)))
    first = np.ceil(max(lo, step) / step) * step
    return [float(v) for v in np.arange(first, hi + 1e-9, step)]


def plot_pile_comparison(omega, open_sea, with_pile, betas, path, title: str = ""):
    """Save :func:`figure_pile_comparison` to ``path``."""
    return _save(figure_pile_comparison(omega, open_sea, with_pile, betas, title=title), path, dpi=110)


def figure_pile_comparison(omega, open_sea, with_pile, betas, *, title: str = ""):
    """Heave and pitch RAO magnitudes in the open sea and beside the pile, one column per heading."""
    plt = _pyplot()
    fig, axes = plt.subplots(2, len(betas), figsize=(3.2 * len(betas), 5.5), sharex=True, squeeze=False)
    T = 2 * np.pi / np.asarray(omega)
    for j, b in enumerate(betas):
        for i, (d, name, scale) in enumerate(((2, "heave RAO [m/m]", 1.0), (4, "pitch RAO [deg/m]", 180 / np.pi))):
            ax = axes[i, j]
            ax.plot(T, scale * np.abs(open_sea[:, j, d]), label="open sea")
            ax.plot(T, scale * np.abs(with_pile[:, j, d]), label="beside the pile")
            ax.grid(alpha=0.3)
            if j == 0:
                ax.set_ylabel(name)
            if i == 0:
                ax.set_title(f"β = {b:g}°")
            else:
                ax.set_xlabel("wave period [s]")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    return fig


def plot_shear_sweep(sweep, path: str | Path, *, title: str = "") -> Path:
    """Save :func:`figure_shear_sweep` to ``path``."""
    return _save(figure_shear_sweep(sweep, title=title), path)


def figure_shear_sweep(sweep, *, title: str = ""):
    """Limiting Hs [m] against the fender's shear stiffness per contact [N/m] (log axis; the rigid stick
    drawn as a dashed level at the right), one line per relative wave direction
    (:func:`boatland.freqdomain.screening.shear_sweep`)."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.8), constrained_layout=True)
    finite = np.isfinite(sweep.k_t)
    betas = list(sweep.beta_deg)
    for j, b in enumerate(sweep.beta_deg):
        mirror = (360.0 - b) % 360.0
        if b > 180.0 and mirror in betas and np.allclose(sweep.Hs[:, j], sweep.Hs[:, betas.index(mirror)], rtol=1e-9):
            continue                                   # port–starboard mirror of a drawn direction
        line, = ax.plot(sweep.k_t[finite], sweep.Hs[finite, j], marker="o", label=f"{b:g}°")
        if (~finite).any():
            ax.axhline(sweep.Hs[~finite, j][0], color=line.get_color(), ls="--", lw=0.8)
    ax.set_xscale("log")
    ax.set(xlabel="shear stiffness k_t per contact [N/m] (dashed: rigid stick)", ylabel="limiting Hs [m]",
           title=title or f"limiting Hs at Tp {sweep.Tp:g} s")
    ax.title.set_fontsize(9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(title="relative direction (180° = head seas;\nits mirror 360° − β is the same)", fontsize=8, ncol=2)
    return fig
