"""The operability figure: availability per calendar month — each vessel's best-landing choice as bars, each
landing alone as ticks — and, when a window was asked for, the probability of a window per month; for a
scatter diagram (no months), availability per landing."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from boatland.site.operability import MONTHS, Operability

__all__ = ["figure_operability", "plot_operability"]

#: One marker per landing alone (the bars are the best choice).
MARKERS = ("_", "x", "+", "1", "4", "|")


def figure_operability(results: list[Operability], *, title: str = ""):
    """The figure (module docstring) of one or more vessels over the same weather."""
    from boatland.plotstyle import pyplot

    plt = pyplot()
    hindcast = results[0].weather.time is not None
    windows = hindcast and bool(results[0].windows)
    fig, axes = plt.subplots(2 if windows else 1, 1, figsize=(10.5, 6.2 if windows else 3.8), squeeze=False,
                             constrained_layout=True, sharex=True)
    colours = plt.cm.tab10.colors
    k = len(results)
    width = 0.8 / k
    for s, r in enumerate(results):
        c = colours[s % 10]
        if hindcast:
            x = np.arange(12) + (s - (k - 1) / 2) * width
            mon = r.monthly()
            axes[0, 0].bar(x, 100 * mon[:, -1], width * 0.92, color=c, alpha=0.85,
                           label=f"{r.name}: best landing, {100 * r.availability()[-1]:.1f} % a year")
            for j in range(r.landings_deg.size):
                axes[0, 0].plot(x, 100 * mon[:, j], ls="none", marker=MARKERS[j % len(MARKERS)], ms=6, mew=1.3,
                                color="0.1", label=f"landing {r.landings_deg[j]:g}° alone" if s == 0 else None)
            if windows:
                wm = r.window_monthly()
                axes[1, 0].bar(x, 100 * wm[:, -1], width * 0.92, color=c, alpha=0.85,
                               label=f"{r.name}: P = {100 * r.windows[-1].probability():.1f} % a year")
        else:
            x = np.arange(r.landings_deg.size + 1) + (s - (k - 1) / 2) * width
            axes[0, 0].bar(x, 100 * r.availability(), width * 0.92, color=c, alpha=0.85, label=r.name)
    ax = axes[0, 0]
    ax.set_ylabel("available [% of the time]")
    ax.set_ylim(0, _top(ax))
    ax.grid(axis="y", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    lim = results[0].limits
    ax.set_title(title or f"access over {results[0].weather.describe()}\nμ·F_b as in each scenario, P_acc "
                 f"{lim.accept:g} per {lim.access_duration:g} s access ({lim.statistics})", fontsize=8.5)
    if hindcast:
        axes[-1, 0].set_xticks(np.arange(12))
        axes[-1, 0].set_xticklabels(MONTHS)
    else:
        axes[-1, 0].set_xticks(np.arange(lim.landings_deg.size + 1))
        axes[-1, 0].set_xticklabels([f"landing {b:g}°" for b in lim.landings_deg] + ["best landing"])
    if windows:
        ax = axes[1, 0]
        ax.set_ylabel(f"P(a {results[0].window_hours:g}-h window starts) [%]")
        ax.set_ylim(0, _top(ax))
        ax.grid(axis="y", alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return fig


def _top(ax) -> float:
    """The axis' top [%]: the largest bar or marker and a margin, at least 10 %, at most 100 %."""
    values = [p.get_height() for p in ax.patches] + [y for line in ax.get_lines() for y in line.get_ydata()]
    finite = [v for v in values if np.isfinite(v)]
    return float(min(100.0, max(10.0, 1.15 * max(finite, default=0.0))))


def plot_operability(results: list[Operability], path: str | Path, *, title: str = "", dpi: int = 110) -> Path:
    """Save :func:`figure_operability` to ``path`` (PNG, SVG or PDF by its suffix), written whole or not at all."""
    from boatland.plotstyle import save_figure

    return save_figure(figure_operability(results, title=title), path, dpi=dpi)
