"""A report figure of a run log: motions, fender forces against the available friction, slip distance,
with the events marked (``boatland plot run.mcap -o fig.png``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from boatland.record.reader import RunLog

__all__ = ["plot_run", "figure_of_run", "PANELS"]

PANELS = ("Motions", "Fender forces", "Slip distance")


def plot_run(log: RunLog, output: str | Path, *, dpi: int = 110) -> Path:
    """Write the figure of ``log`` to ``output`` (format from the suffix, e.g. .png, .pdf, .svg)."""
    import matplotlib.pyplot as plt

    fig = figure_of_run(log)
    output = Path(output)
    fig.savefig(output, dpi=dpi)
    plt.close(fig)
    return output


def figure_of_run(log: RunLog):
    """The matplotlib Figure: three panels (:data:`PANELS`) sharing the time axis."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    c = log.columns
    t = c.t
    fig, axes = plt.subplots(3, 1, figsize=(10, 8.5), sharex=True, constrained_layout=True)
    ax = axes[0]
    ax.plot(t, c.x[:, 2], lw=0.8, label="heave [m]")
    ax.plot(t, np.degrees(c.x[:, 3]), lw=0.8, label="roll [deg]")
    ax.plot(t, np.degrees(c.x[:, 4]), lw=0.8, label="pitch [deg]")
    ax.set_title(PANELS[0])
    ax.set_ylabel("m, deg")
    ax.legend(loc="upper right", ncol=3, fontsize=8)
    ax = axes[1]
    for k in range(c.mode.shape[1]):
        style = dict(lw=0.8 if k == 0 else 0.6, alpha=1.0 if k == 0 else 0.6, ls="-" if k == 0 else ":")
        ax.plot(t, c.fn[:, k] / 1e3, color="tab:blue", label=f"contact {k} normal", **style)
        ax.plot(t, c.needed[:, k] / 1e3, color="tab:red", label=f"contact {k} needed to stick", **style)
        ax.plot(t, c.available[:, k] / 1e3, color="tab:green", label=f"contact {k} available μ f_n", **style)
    ax.set_title(PANELS[1] + " (normal, friction needed to stick, friction available)")
    ax.set_ylabel("kN")
    ax.legend(loc="upper right", ncol=3, fontsize=7)
    ax = axes[2]
    for k in range(c.mode.shape[1]):
        ax.plot(t, c.slip[:, k], lw=0.9, label=f"contact {k}")
    limits = []
    if log.summary is not None:
        limits = [float(k.split(">")[1].split("m")[0]) for k in log.summary.get("incidents", {}) if k.startswith("slip >")]
    for lim in limits:
        ax.axhline(lim, color="0.5", lw=0.6, ls=":")
    ax.set_title(PANELS[2] + " from the landing position")
    ax.set_ylabel("m")
    ax.set_xlabel("t [s]")
    ax.legend(loc="upper left", fontsize=8)
    slips = [e[0] for e in log.events if "stick→slip" in e[2]]
    incidents = [e[0] for e in log.events if e[2].startswith("incident")]
    for a in axes:
        for ts in slips:
            a.axvline(ts, color="tab:red", lw=0.4, alpha=0.35)
        for ts in incidents:
            a.axvline(ts, color="k", lw=0.8, ls="--")
    name = log.metadata.get("scenario_name", log.path.stem)
    title = f"{name} (seed {log.metadata.get('seed', '?')}): {len(slips)} slip events; red = slip start, dashed = incident"
    if not log.complete:
        title += " — truncated log"
    fig.suptitle(title, fontsize=10)
    return fig
