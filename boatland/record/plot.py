"""A report figure of a run log (``boatland plot run.mcap -o fig.png``): does the fender hold, and why.

Panels sharing the time axis (:data:`PANELS`):

1. the wave elevation at the bow (with the pile's scattered wave when the trial has it) and heave [m];
2. roll and pitch [deg];
3. friction utilisation per contact — the friction needed to hold the contact stuck over the friction
   available (μ_s f_n stuck, μ(|u|) f_n sliding); at 1 the contact slips (the line at 1); in runs
   longer than 3 minutes drawn as its largest value per peak period (the rest faint);
4. normal force per contact [kN];
5. slip distance of each fender point from where it landed, with the incident thresholds.

Contacts that do exactly the same (a symmetric landing in head seas) are one line, "contacts 0+1".
The settling (the thrust ramping in) is shaded; slip starts (contacts slipping at the same step once)
are ticks along the top of the utilisation panel, thinned to one per 0.5 % of the time axis when
there are many; incidents are labelled dashed lines. The title names the inputs (sea, direction, push,
μ, seed) and the verdict.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from boatland.record.reader import RunLog
from boatland.trial.incidents import SlipDistance, parse_incident

__all__ = ["plot_run", "figure_of_run", "PANELS"]

PANELS = ("Wave at the bow and heave", "Roll and pitch", "Friction utilisation", "Normal force", "Slip distance")

#: Utilisation shown up to this value (a slipping contact's trial force can be far above 1).
UTIL_MAX = 1.6



def _definition(name: str):
    """The incident definition a logged name stands for (None: a name this version does not know)."""
    try:
        return parse_incident(name)
    except ValueError:
        return None

def plot_run(log: RunLog, output: str | Path, *, dpi: int = 110) -> Path:
    """Write the figure of ``log`` to ``output`` (format from the suffix, e.g. .png, .pdf, .svg)."""
    from boatland.plotstyle import save_figure

    return save_figure(figure_of_run(log), output, dpi=dpi)


def _provenance(log: RunLog) -> dict:
    import json

    try:
        return json.loads(log.metadata.get("provenance", "{}"))
    except (TypeError, ValueError):
        return {}


def _title(log: RunLog, prov: dict) -> str:
    from boatland.scenario.inputs import short_inputs_text

    name = log.metadata.get("scenario_name", prov.get("scenario", log.path.stem))
    if prov.get("database"):
        name = f"{name} ({prov['database']})"
    inputs = prov.get("inputs", {})
    seed = log.metadata.get("seed", prov.get("seed", "?"))
    line1 = f"{name}: {short_inputs_text(inputs)}; seed {seed}" if inputs else f"{name} (seed {seed})"
    verdict = ((log.summary or {}).get("verdict") or {}).get("headline")
    if verdict is None and log.summary is not None:
        hit = [f"{k} at t = {t:.1f} s" for k, t in log.summary.get("incidents", {}).items() if t is not None]
        verdict = "incidents: " + (", ".join(hit) if hit else "none")
    line2 = verdict or "(no summary: the run did not finish writing its log)"
    if not log.complete:
        line2 += " — truncated log"
    return f"{line1}\n{line2}"


def _wave_period(prov: dict) -> float:
    """The sea's peak period [s] (window of the utilisation envelope); 10 s when unknown."""
    inputs = prov.get("inputs", {})
    for key in ("Tp", "T"):
        if inputs.get(key):
            return float(inputs[key])
    return 10.0


def _thin(times: np.ndarray, span: float, fraction: float = 0.005) -> np.ndarray:
    """Times at least ``fraction`` of ``span`` apart (the first of each cluster kept)."""
    out, last = [], -np.inf
    for t in np.sort(times):
        if t - last >= fraction * span:
            out.append(t)
            last = t
    return np.asarray(out)


def _distinct(a: np.ndarray) -> list[tuple[str, np.ndarray]]:
    """Columns of ``a`` (n, Nc) with their labels, identical ones once ("contacts 0+1": a symmetric
    landing's tubes in head seas)."""
    groups: list[tuple[list[int], np.ndarray]] = []
    for k in range(a.shape[1]):
        for members, col in groups:
            if np.allclose(col, a[:, k], rtol=1e-9, atol=1e-12, equal_nan=True):
                members.append(k)
                break
        else:
            groups.append(([k], a[:, k]))
    return [(("contact " if len(m) == 1 else "contacts ") + "+".join(map(str, m)), col) for m, col in groups]


def _envelope(t: np.ndarray, y: np.ndarray, window: float) -> tuple[np.ndarray, np.ndarray]:
    """Largest value of ``y`` in consecutive windows of ``window`` seconds (NaN ignored), as steps."""
    if len(t) < 2 or window <= 0:
        return t, y
    edges = np.arange(t[0], t[-1] + window, window)
    idx = np.searchsorted(t, edges)
    tops = [np.nanmax(y[i:j]) if j > i and np.isfinite(y[i:j]).any() else np.nan for i, j in zip(idx[:-1], idx[1:])]
    return edges[:-1], np.asarray(tops)


def figure_of_run(log: RunLog):
    """The matplotlib Figure of a run log (module docstring); axes titled with :data:`PANELS`."""
    from boatland.plotstyle import pyplot

    plt = pyplot()
    c = log.columns
    t = c.t
    prov = _provenance(log)
    settled = float(prov.get("waves_from", 0.0))
    fig, axes = plt.subplots(5, 1, figsize=(11, 11), sharex=True, layout="constrained",
                             gridspec_kw={"height_ratios": [1.1, 1, 1.1, 0.8, 1]})
    ax = axes[0]
    ax.plot(t, c.eta_bow, lw=0.7, color="tab:cyan", label="wave elevation at the bow")
    ax.plot(t, c.x[:, 2], lw=0.9, color="tab:blue", label="heave of the reference point")
    ax.set(title=PANELS[0], ylabel="elevation, heave [m]")
    ax = axes[1]
    ax.plot(t, np.degrees(c.x[:, 3]), lw=0.8, color="tab:purple", label="roll")
    ax.plot(t, np.degrees(c.x[:, 4]), lw=0.8, color="tab:orange", label="pitch")
    ax.set(title=PANELS[1], ylabel="angle [deg]")
    ax = axes[2]
    with np.errstate(divide="ignore", invalid="ignore"):
        util = np.where(c.available > 0, c.needed / np.where(c.available > 0, c.available, 1.0), np.nan)
    long_run = len(t) > 1 and (t[-1] - t[0]) > 180.0
    window = _wave_period(prov)
    for j, (label, col) in enumerate(_distinct(util)):
        y = np.clip(col, 0, UTIL_MAX)
        if long_run:      # hundreds of waves: the largest utilisation per wave period, the rest faint
            ax.plot(t, y, lw=0.4, alpha=0.25, color=f"C{j}")
            te, ye = _envelope(t, y, window)
            ax.step(te, ye, where="post", lw=1.0, color=f"C{j}", label=f"{label}: largest per {window:g} s")
        else:
            ax.plot(t, y, lw=0.8, color=f"C{j}", ls="-" if j == 0 else "--", label=label)
    ax.axhline(1.0, color="tab:red", lw=1.0, label="slips at 1")
    ax.set(title=PANELS[2] + " (friction needed to stick / available; clipped at "
                             f"{UTIL_MAX:g})", ylabel="needed / available [-]", ylim=(0, UTIL_MAX * 1.08))
    ax = axes[3]
    for j, (label, col) in enumerate(_distinct(c.fn)):
        ax.plot(t, col / 1e3, lw=0.7, ls="-" if j == 0 else "--", label=label)
    ax.set(title=PANELS[3], ylabel="normal force [kN]")
    ax = axes[4]
    for j, (label, col) in enumerate(_distinct(c.slip)):
        ax.plot(t, col, lw=0.9, ls="-" if j == 0 else "--", label=label)
    limits = []
    if log.summary is not None:
        kinds = [_definition(k) for k in log.summary.get("incidents", {})]
        limits = [d.distance for d in kinds if isinstance(d, SlipDistance)]
    for lim in limits:
        ax.axhline(lim, color="0.5", lw=0.7, ls=":")
        ax.annotate(f"{lim:g} m", (1.0, lim), xycoords=("axes fraction", "data"), fontsize=7, color="0.35",
                    ha="right", va="bottom")
    ax.set(title=PANELS[4] + " of each fender point from where it landed", ylabel="distance [m]", xlabel="time [s]")
    # settling, slip starts, incidents
    span = float(t[-1] - t[0]) if len(t) > 1 else 1.0
    for a in axes:
        if settled > 0:
            a.axvspan(t[0], min(settled, t[-1]), color="0.85", alpha=0.6, lw=0, zorder=0)
        a.grid(alpha=0.3)
    if settled > 0:
        axes[0].text(settled / 2, 0.97, "settling", transform=axes[0].get_xaxis_transform(), ha="center", va="top",
                     fontsize=7, color="0.3")
    starts = np.unique([e[0] for e in log.events if "stick→slip" in e[2] and e[0] >= settled - 1e-9])
    shown = _thin(starts, span)
    if shown.size:
        axes[2].plot(shown, np.full(shown.size, UTIL_MAX * 1.04), "|", color="tab:red", ms=7, mew=1.0,
                     label=f"slip start ({starts.size}" + (f", {shown.size} shown)" if shown.size < starts.size else ")"))
    incidents = {}
    for ts, _, text in log.events:
        if text.startswith("incident"):
            incidents.setdefault(text[len("incident:"):].split(" at t =")[0].strip() or text, ts)
    if log.summary is not None:      # the finished run's own list: contact loss and sliding off too
        incidents.update({k: v for k, v in log.summary.get("incidents", {}).items() if v is not None})
    for i, (name, ts) in enumerate(sorted(incidents.items(), key=lambda kv: kv[1])[:6]):
        for a in axes:
            a.axvline(ts, color="k", lw=0.8, ls="--")
        axes[4].annotate(name, (ts, 1.0 - 0.12 * i), xycoords=("data", "axes fraction"), fontsize=7, rotation=0,
                         ha="left", va="top", xytext=(3, 0), textcoords="offset points")
    for a in axes:
        a.legend(loc="upper right", fontsize=7, ncol=4, framealpha=0.8,
                 bbox_to_anchor=(1.0, 0.92) if a is axes[2] else None)
    fig.suptitle(_title(log, prov), fontsize=9)
    return fig
