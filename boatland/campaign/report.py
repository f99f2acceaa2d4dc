"""Reports of a campaign store: tables (CSV and Markdown) and figures.

- ``cases.csv`` / ``cases.md``: per case, every incident definition's count, P(incident within the
  access) with its Clopper–Pearson 95 % interval and the mean time to the incident with its χ²
  interval (:mod:`boatland.campaign.stats`);
- ``limiting_hs.csv`` / ``.md``: when ``sea.Hs`` is an axis, the limiting Hs at the target
  probability per combination of the other axes;
- ``p_vs_hs.png``: P(incident) against Hs with intervals, one line per combination of the other axes;
- ``limiting_hs_polar.png``: limiting Hs against the heading, one line per Tp (with a direction axis);
- ``time_to_incident.png``: empirical distribution of the time to the first incident per case.

A campaign by importance sampling (``method = "isee"``, :mod:`boatland.campaign.isee`) gets instead:

- ``isee_runs.csv`` / ``.md``: per run (case × Hs level) the estimate of every incident with its CoV and
  95 % interval, the linear model's first slip (friction circle) and the screening's square, the sampling
  domain, the bounds (largest elementary probability, Rice), the frequency-domain screening (Rayleigh,
  Rice, Vanmarcke) and how many time-domain slips the linear model did not have;
- ``isee_limits.csv`` / ``.md`` (with ``accept``): the limiting Hs per case from the time domain with its
  interval, beside the linear model's and the screening's;
- ``p_vs_hs.png``: the estimates against Hs; ``limiting_hs_polar.png``: the limiting Hs against the
  heading, time domain (with intervals) and screening, one colour per Tp.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np

from boatland.campaign.runner import completed
from boatland.campaign.stats import limiting_hs
from boatland.campaign.store import FORMAT, INCIDENT_PREFIX
from boatland.errors import BoatlandInputError

__all__ = ["read_store", "write_report", "REPORT_FILES"]

#: Every file :func:`write_report` may write into its folder.
REPORT_FILES = ("cases.csv", "cases.md", "limiting_hs.csv", "limiting_hs.md", "p_vs_hs.png",
                "limiting_hs_polar.png", "time_to_incident.png", "isee_runs.csv", "isee_runs.md", "isee_limits.csv",
                "isee_limits.md")

HS_KEY = "sea.Hs"
DIR_KEYS = ("sea.relative_direction_deg", "sea.direction_deg")
TP_KEYS = ("sea.Tp",)


def read_store(path: str | Path) -> dict:
    """The store's header, trial rows and statistics (raises a one-line error for anything else)."""
    import h5py

    path = Path(path)
    if not path.is_file():
        raise BoatlandInputError(f"{path}: no such file")
    try:
        with h5py.File(path, "r") as f:
            if f.attrs.get("format") != FORMAT:
                raise BoatlandInputError(f"{path}: not a boatland campaign store")
            header = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
            if "trials" not in f or not isinstance(f["trials"], h5py.Dataset):
                raise BoatlandInputError(f"{path}: a campaign store without trials (nothing has run yet); run "
                                         "the campaign first")
            trials = f["trials"][()]
            stats = f["stats"][()] if "stats" in f else None
            limits = f["isee_limits"][()] if "isee_limits" in f else None
    except OSError as exc:
        raise BoatlandInputError(f"{path}: not a readable HDF5 file ({exc})") from None
    if stats is None:
        raise BoatlandInputError(f"{path}: the campaign has not finished (no statistics yet); run it again to resume")
    if trials.size == 0 or stats.size == 0:
        raise BoatlandInputError(f"{path}: a campaign store without trials; nothing to report")
    try:
        plan = json.loads(header["plan"])
        header["incidents"].split("\n")
    except (KeyError, ValueError, TypeError, AttributeError):
        raise BoatlandInputError(f"{path}: a damaged campaign store (its plan or incident list is missing)") from None
    out = {"header": header, "trials": trials, "stats": stats, "plan": plan}
    if limits is not None:
        out["isee_limits"] = limits
    return out


def write_report(store: str | Path, out_dir: str | Path, *, incident: str | None = None,
                 target: float = 0.1, figures: bool = True) -> list[Path]:
    """Write the tables and figures of a finished campaign into ``out_dir``; returns the files.

    Parameters
    ----------
    incident : str, optional
        Incident definition of the limiting-Hs table and figures (default: the first slip distance
        definition, else "first slip").
    target : float
        Accepted probability of the incident within the access, for the limiting Hs.
    """
    data = read_store(store)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    if data["header"].get("method") == "isee":
        return _isee_report(data, out, incident, figures)
    stats, plan = data["stats"], data["plan"]
    names = data["header"]["incidents"].split("\n")
    if incident is None:
        incident = next((n for n in names if n.startswith("slip >")), names[0])
    if incident not in names:
        raise BoatlandInputError(f"incident {incident!r} is not one of the campaign's: {', '.join(names)}")
    files = [*_cases_tables(stats, names, out)]
    axes = list(plan["axes"])
    if HS_KEY in axes:
        files += _limiting_tables(stats, axes, incident, target, out)
    if figures:
        files += _figures(data, axes, incident, target, out)
    return files


def _fmt(v) -> str:
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, (float, np.floating)):
        return "" if math.isnan(v) else ("inf" if math.isinf(v) else f"{v:.4g}")
    return str(v)


def _write_tables(rows: list[list], header: list[str], out: Path, stem: str, title: str) -> list[Path]:
    csv_path, md_path = out / f"{stem}.csv", out / f"{stem}.md"
    with open(csv_path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows([[_fmt(v) for v in r] for r in rows])
    lines = [f"# {title}", "", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(_fmt(v) for v in r) + " |" for r in rows]
    md_path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return [csv_path, md_path]


def _cases_tables(stats, names, out):
    header = ["case", "label", "trials", "failed", "screening: P(slip) (frequency domain)", "screening: note"]
    for n in names:
        header += [f"{n}: count", f"{n}: P", f"{n}: P lo", f"{n}: P hi", f"{n}: mean time [s]",
                   f"{n}: mean lo", f"{n}: mean hi"]
    cols = ["case", "label", "trials", "failed", "screening: P(slip)", "screening: note"] + [f"{n}: {k}" for n in names
                                                   for k in ("count", "P", "P lo", "P hi", "mean time", "mean lo", "mean hi")]
    rows = [[r[c] for c in cols] for r in stats]
    return _write_tables(rows, header, out, "cases", "Per case: incident probability (Clopper–Pearson 95 %) "
                                                      "and mean time to the incident (χ² 95 %)")


def _groups(stats, axes):
    """Combinations of the axes other than Hs → indices of their cases, in plan order."""
    others = [a for a in axes if a != HS_KEY]
    groups: dict[tuple, list[int]] = {}
    for i, r in enumerate(stats):
        groups.setdefault(tuple(float(r[f"axis: {a}"]) for a in others), []).append(i)
    return others, groups


def _limiting_tables(stats, axes, incident, target, out):
    others, groups = _groups(stats, axes)
    rows = []
    for key, idx in groups.items():
        hs = stats[f"axis: {HS_KEY}"][idx]
        p = stats[f"{incident}: P"][idx]
        rows.append([*key, limiting_hs(hs, p, target)])
    return _write_tables(rows, [*others, f"limiting Hs [m] at P({incident}) = {target:g}"], out, "limiting_hs",
                         f"Limiting Hs: P({incident} within the access) = {target:g}, linear interpolation along Hs")


def _figures(data, axes, incident, target, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    stats, trials = data["stats"], data["trials"]
    files = []
    if HS_KEY in axes:
        others, groups = _groups(stats, axes)
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for key, idx in groups.items():
            hs = stats[f"axis: {HS_KEY}"][idx]
            p, lo, hi = (stats[f"{incident}: {k}"][idx] for k in ("P", "P lo", "P hi"))
            label = ", ".join(f"{a.split('.')[-1]} {v:g}" for a, v in zip(others, key)) or "all"
            ax.errorbar(hs, p, yerr=[p - lo, hi - p], marker="o", capsize=3, label=label)
        ax.axhline(target, color="0.5", ls="--", lw=1, label=f"target {target:g}")
        ax.set(xlabel="Hs [m]", ylabel=f"P({incident} within the access)", ylim=(-0.02, 1.02),
               title=f"{data['header']['campaign']}: incident probability (Clopper–Pearson 95 %)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        files.append(_save(fig, out / "p_vs_hs.png"))
        dkey = next((k for k in DIR_KEYS if k in axes), None)
        if dkey is not None:
            tkey = next((k for k in TP_KEYS if k in axes), None)
            fig = plt.figure(figsize=(5.5, 5.5))
            ax = fig.add_subplot(projection="polar")
            tps = sorted({float(r[f"axis: {tkey}"]) for r in stats}) if tkey else [None]
            for tp in tps:
                dirs, lim = [], []
                for d in sorted({float(r[f"axis: {dkey}"]) for r in stats}):
                    sel = [i for i, r in enumerate(stats) if float(r[f"axis: {dkey}"]) == d
                           and (tp is None or float(r[f"axis: {tkey}"]) == tp)]
                    dirs.append(np.radians(d))
                    lim.append(limiting_hs(stats[f"axis: {HS_KEY}"][sel], stats[f"{incident}: P"][sel], target))
                ax.plot(dirs, lim, marker="o", label="all" if tp is None else f"Tp {tp:g} s")
            ax.set_theta_zero_location("N")
            ax.set_title(f"limiting Hs [m], P({incident}) = {target:g}\n(heading relative to the bow)", fontsize=9)
            ax.legend(fontsize=8, loc="lower left")
            files.append(_save(fig, out / "limiting_hs_polar.png"))
    fig, ax = plt.subplots(figsize=(7, 4.5))
    col = INCIDENT_PREFIX + incident
    for r in stats:
        t = trials[col][(trials["case"] == r["case"]) & completed(trials)]
        if not np.isfinite(t).any():
            continue
        ts = np.sort(t[np.isfinite(t)])
        ax.step(np.r_[0, ts], np.arange(ts.size + 1) / t.size, where="post", label=_fmt(r["label"]))
    ax.set(xlabel="time to the first incident after the waves start [s]", ylabel="fraction of trials",
           title=f"time to {incident} (empirical; censored trials never reach the top)")
    ax.grid(alpha=0.3)
    if len(stats) <= 12:
        ax.legend(fontsize=7)
    files.append(_save(fig, out / "time_to_incident.png"))
    return files


def _save(fig, path: Path) -> Path:
    import matplotlib.pyplot as plt

    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


# ---------------------------------------------------------------------------------------- isee
def _isee_report(data, out: Path, incident: str | None, figures: bool) -> list[Path]:
    runs, plan = data["stats"], data["plan"]
    names = data["header"]["incidents"].split("\n")
    settings = json.loads(data["header"].get("isee", "{}"))
    inc = incident or settings.get("incident", "first slip")
    if inc not in names:
        raise BoatlandInputError(f"incident {inc!r} is not one of the campaign's: {', '.join(names)}")
    head = ["case", "label", "Hs [m]", "samples", "failed", f"P({inc})", "CoV", "P lo", "P hi",
            "linear first slip (circle)", "linear square (screening's margins)", "sampling domain",
            "largest elementary P", "Rice bound", "screening Rayleigh", "screening Rice", "screening Vanmarcke",
            "TD slips outside the linear slip", "CPU [s]"]
    rows = [[r["case"], r["label"], r["hs"], r["samples"], r["failed"], r[f"{inc}: P"], r[f"{inc}: CoV"],
             r[f"{inc}: P lo"], r[f"{inc}: P hi"], r["linear first slip: P"], r["linear square: P"], r["domain: P"],
             r["largest elementary P"], r["rice bound"], r["screening rayleigh"], r["screening rice"],
             r["screening vanmarcke"], r["TD slip outside linear slip"], r["wall time"]] for r in runs]
    files = _write_tables(rows, head, out, "isee_runs",
                          f"ISEE runs: P({inc} within the access), time domain on the sampled seas (95 % interval), "
                          "beside the linear model, its bounds and the frequency-domain screening")
    lim = data.get("isee_limits")
    if lim is not None:
        axes = [a for a in plan["axes"]]
        head = ["case", "label", *axes, "limiting Hs [m]", "lo", "hi", "linear model [m]", "lo", "hi",
                "screening Rayleigh [m]", "screening Rice [m]", "screening Vanmarcke [m]", "levels", "samples"]
        rows = [[L["case"], L["label"], *[L[f"axis: {a}"] for a in axes], L["limiting Hs"], L["limiting Hs lo"],
                 L["limiting Hs hi"], L["linear limiting Hs"], L["linear limiting Hs lo"], L["linear limiting Hs hi"],
                 L["screening rayleigh Hs"], L["screening rice Hs"], L["screening vanmarcke Hs"], L["levels"],
                 L["samples"]] for L in lim]
        acc = float(lim["accept"][0]) if lim.size else math.nan
        files += _write_tables(rows, head, out, "isee_limits",
                               f"Limiting Hs at P({inc} within the access) = {acc:g}: time domain by ISEE (95 % "
                               "interval), the linear model, the frequency-domain screening")
    if figures:
        files += _isee_figures(runs, lim, plan, inc, out)
    return files


def _isee_figures(runs, lim, plan, inc, out):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    files = []
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for c in np.unique(runs["case"]):
        r = runs[runs["case"] == c]
        r = r[np.argsort(r["hs"])]
        p, lo, hi = r[f"{inc}: P"], r[f"{inc}: P lo"], r[f"{inc}: P hi"]
        ax.errorbar(r["hs"], p, yerr=[np.maximum(p - lo, 0), np.maximum(hi - p, 0)], marker="o", capsize=3,
                    label=_fmt(r["label"][0]) or "base")
    ax.set(xlabel="Hs [m]", ylabel=f"P({inc} within the access)", yscale="log",
           title="ISEE: time domain on the sampled seas (95 %)")
    ax.grid(alpha=0.3, which="both")
    if runs.size <= 40:
        ax.legend(fontsize=7)
    files.append(_save(fig, out / "p_vs_hs.png"))
    axes = list(plan["axes"])
    dkey = next((k for k in DIR_KEYS if k in axes), None)
    if lim is not None and dkey is not None:
        tkey = next((k for k in TP_KEYS if k in axes), None)
        fig = plt.figure(figsize=(6, 6))
        ax = fig.add_subplot(projection="polar")
        tps = sorted({float(x) for x in lim[f"axis: {tkey}"]}) if tkey else [None]
        for i, tp in enumerate(tps):
            sel = lim if tp is None else lim[lim[f"axis: {tkey}"] == tp]
            sel = sel[np.argsort(sel[f"axis: {dkey}"])]
            th = np.radians(sel[f"axis: {dkey}"])
            colour = f"C{i % 10}"
            label = "all" if tp is None else f"Tp {tp:g} s"
            ax.errorbar(th, sel["limiting Hs"], yerr=[np.maximum(sel["limiting Hs"] - sel["limiting Hs lo"], 0),
                                                       np.maximum(sel["limiting Hs hi"] - sel["limiting Hs"], 0)],
                        marker="o", color=colour, capsize=2, label=f"{label}: time domain (ISEE)")
            ax.plot(th, sel["screening rayleigh Hs"], ls="--", color=colour, lw=1, label=f"{label}: screening")
        ax.set_theta_zero_location("N")
        acc = float(lim["accept"][0])
        ax.set_title(f"limiting Hs [m] at P({inc}) = {acc:g} per access\n(heading relative to the bow)", fontsize=9)
        ax.legend(fontsize=6, loc="lower left", bbox_to_anchor=(-0.1, -0.15), ncol=2)
        files.append(_save(fig, out / "limiting_hs_polar.png"))
    return files
