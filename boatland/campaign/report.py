"""Reports of a campaign store: the decision table, tables (CSV and Markdown) and figures.

- ``report.html``: one self-contained page to decide from — provenance, inputs, the incident and the
  accepted risk in words, the decision table, the sensitivity (when given) and every figure embedded
  (:mod:`boatland.campaign.html`);
- ``decision.md`` / ``decision.csv``: what a planner reads — P(incident within the access) [95 %
  interval] pivoted by Hs × Tp × heading, the limiting Hs with its interval and the seeds an interval of
  the asked width needs (:mod:`boatland.campaign.decision`); the frequency-domain screening, which
  predicts slip onsets, beside the cells of the incident "first slip" only (like with like);
- ``limiting_hs.csv`` / ``.md``: when ``sea.Hs`` is an axis, the limiting Hs at the target
  probability with its interval per combination of the other axes ("< lowest swept Hs" / "> highest"
  where it does not cross inside the sweep);
- ``cases.csv`` (every column, for programs) / ``cases.md`` (readable): per case and incident
  definition the count, P with its Clopper–Pearson interval and the mean time to the incident with
  its χ² interval (:mod:`boatland.campaign.stats`), and the screening's P(first slip) named as such;
- ``p_vs_hs.png``: P(incident) against Hs with intervals, one line per Tp × heading (and the
  screening's, dashed, when the incident is "first slip");
- ``limiting_hs_polar.png``: limiting Hs against the heading (bow up, 180° head seas at the top:
  :mod:`boatland.plotstyle`), one line per Tp, its interval shaded;
- ``time_to_incident.png``: empirical distribution of the time to the first incident per case;
- ``sensitivity_tornado.png``: when a sensitivity study is given (:func:`boatland.campaign.html.sensitivity_items`).

A campaign by importance sampling (``method = "isee"``, :mod:`boatland.campaign.isee`) gets instead:

- ``isee_runs.csv`` / ``.md``: per run (case × Hs level) the estimate of the campaign's incident with its
  CoV and 95 % interval, the linear model's first slip (friction circle) and the screening's square, the
  sampling domain, the bounds (largest elementary probability, Rice), the frequency-domain screening's
  P(first slip) (Rayleigh, Rice, Vanmarcke) and how many time-domain slips the linear model did not have —
  every column headed by the incident it is of;
- ``isee_limits.csv`` / ``.md`` (with ``accept``): the limiting Hs per case from the time domain with its
  interval, beside the linear model's and the screening's, each naming its incident;
- ``report.html``: the one page, as above, with the per-case limiting Hs and the per-run estimates;
- ``p_vs_hs.png``: the estimates against Hs; ``limiting_hs_polar.png``: the limiting Hs against the
  heading, time domain (with intervals) and screening, one colour per Tp.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np

from boatland.campaign.decision import DEFAULT_WIDTH, ONSET, Decision, decision, p_text
from boatland.campaign.html import (
    figure_sensitivity,
    isee_page,
    monte_carlo_page,
    sensitivity_items,
    write_page,
)
from boatland.campaign.labels import (
    DIR_KEYS,
    HS_KEY,
    axis_label,
    fixed_text,
    inputs_from_header,
    value_text,
)
from boatland.campaign.runner import completed
from boatland.campaign.store import FORMAT, INCIDENT_PREFIX
from boatland.errors import BoatlandInputError
from boatland.inputs import HDF5_DAMAGE, damage_text, open_hdf5
from boatland.freqdomain.statistics import DEFAULT_STATISTICS
from boatland.trial.incidents import SlipDistance, parse_incident

__all__ = [
    "REPORT_FILES",
    "default_incident",
    "figure_limiting_polar",
    "figure_p_vs_hs",
    "figure_time_to_incident",
    "isee_incident",
    "isee_limits_at",
    "isee_linear",
    "read_store",
    "store_decision",
    "store_sensitivity",
    "write_report",
]

#: Every file :func:`write_report` may write into its folder.
REPORT_FILES = ("report.html", "decision.md", "decision.csv", "cases.csv", "cases.md", "limiting_hs.csv",
                "limiting_hs.md", "p_vs_hs.png", "limiting_hs_polar.png", "time_to_incident.png",
                "sensitivity_tornado.png", "isee_runs.csv", "isee_runs.md", "isee_limits.csv", "isee_limits.md")

TP_KEYS = ("sea.Tp",)


def read_store(path: str | Path) -> dict:
    """The store's header, trial rows and statistics (raises a one-line error for anything else)."""
    import h5py

    path = Path(path)
    store = open_hdf5(path, "campaign store")     # read once, checked: refused here when damaged or not HDF5
    try:
        with store as f:
            if f.attrs.get("format") != FORMAT:
                raise BoatlandInputError(f"{path}: not a boatland campaign store")
            header = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
            if "trials" not in f or not isinstance(f["trials"], h5py.Dataset):
                raise BoatlandInputError(f"{path}: a campaign store without trials (nothing has run yet); run "
                                         "the campaign first")
            trials = f["trials"][()]
            stats = f["stats"][()] if "stats" in f else None
            limits = f["isee_limits"][()] if "isee_limits" in f else None
            sens = f["sensitivity"][()] if "sensitivity" in f else None
    except BoatlandInputError:
        raise
    except HDF5_DAMAGE as exc:
        raise BoatlandInputError(f"{path}: a damaged campaign store ({damage_text(exc)})") from None
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
    if sens is not None:     # what moves the base's limit (boatland.campaign.prepare.case_sensitivity), JSON
        out["sensitivity"] = sens.decode(errors="replace") if isinstance(sens, bytes) else str(sens)
    return out


def default_incident(names: list[str]) -> str:
    """The incident a report is about unless told: the first slip-distance definition, else the first."""
    return next((n for n in names if isinstance(parse_incident(n), SlipDistance)), names[0])


def _incident(data: dict, incident: str | None) -> str:
    names = data["header"]["incidents"].split("\n")
    if incident is None:
        return default_incident(names)
    if incident not in names:
        raise BoatlandInputError(f"--incident {incident!r} is not one of the campaign's: {', '.join(names)}")
    return incident


def store_decision(store: str | Path, *, incident: str | None = None, target: float = 0.1,
                   width: float = DEFAULT_WIDTH) -> Decision:
    """The decision table of a finished campaign store (:func:`boatland.campaign.decision.decision`)."""
    data = read_store(store)
    return decision(data, _incident(data, incident), target, width=width)


def write_report(store: str | Path, out_dir: str | Path, *, incident: str | None = None,
                 target: float = 0.1, width: float = DEFAULT_WIDTH, figures: bool = True,
                 sensitivity=None) -> list[Path]:
    """Write the one page (``report.html``), the decision table, tables and figures of a finished
    campaign into ``out_dir``; returns the files (``report.html`` last).

    Parameters
    ----------
    store : str or Path
        A finished campaign store (:func:`read_store`).
    out_dir : str or Path
        Folder (made if missing).
    incident : str, optional
        Incident definition of the decision table, limiting Hs and figures (default: the first slip
        distance definition, else "first slip"; a rare-event store: its ``[isee] incident``).
    target : float
        Accepted probability of the incident within the access, for the limiting Hs (a rare-event
        store has its own, ``[isee] accept``).
    width : float
        Width asked of the 95 % interval of P near the target, for the seeds advice.
    figures : bool
        Draw the PNG figures (and embed them in the page).
    sensitivity : Sensitivity, or sequence of SensitivityItem or dict, optional
        A sensitivity study to show on the page, as a table and a tornado figure: the result of
        :func:`boatland.freqdomain.sensitivity.sensitivity`, or rows (:func:`boatland.campaign.html.sensitivity_items`);
        without one the page says how to get it.

    Returns
    -------
    list of Path
    """
    data = read_store(store)
    if sensitivity is None:
        sensitivity = store_sensitivity(data, store)
    rows = sensitivity_items(sensitivity)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    if data["header"].get("method") == "isee":      # its own incident (the campaign's [isee] incident)
        inc, files = _isee_report(data, out, incident, figures)
        files += _tornado(sensitivity, rows, out, figures, _campaign_title(data))
        page = isee_page(data, inc, store=Path(store), figures=_pngs(files), sensitivity=sensitivity)
        return files + [write_page(page, out / "report.html")]
    incident = _incident(data, incident)
    stats, plan = data["stats"], data["plan"]
    names = data["header"]["incidents"].split("\n")
    dec = decision(data, incident, target, width=width)
    (out / "decision.md").write_text(dec.markdown(), encoding="utf-8")
    files = [out / "decision.md", _decision_csv(dec, out / "decision.csv")]
    axes = list(plan["axes"])
    files += _cases_tables(stats, names, axes, dec, out)
    if HS_KEY in axes:
        files += _limiting_tables(dec, out)
    if figures:
        files += _figures(data, dec, out)
    files += _tornado(sensitivity, rows, out, figures, _campaign_title(data))
    page = monte_carlo_page(data, dec, store=Path(store), figures=_pngs(files), sensitivity=sensitivity)
    return files + [write_page(page, out / "report.html")]


def _pngs(files: list[Path]) -> list[Path]:
    return [f for f in files if f.suffix == ".png"]


def _tornado(sensitivity, rows, out: Path, figures: bool, title: str = "") -> list[Path]:
    if not rows or not figures:
        return []
    from boatland.plotstyle import save_figure

    return [save_figure(figure_sensitivity(sensitivity, title), out / "sensitivity_tornado.png")]


def _campaign_title(data: dict) -> str:
    """"campaign: what moves the limit" and the campaign's fixed inputs (push, μ, seeds …), for a figure."""
    header, plan = data["header"], data["plan"]
    fixed = fixed_text(inputs_from_header(header), list(plan["axes"]))
    seeds = f"{plan['seeds']} seeds per case" if plan.get("seeds") else ""
    return f"{header.get('campaign', '')}: what moves the limit — " + "; ".join(x for x in (fixed, seeds) if x)


def isee_limits_at(data: dict, Tp: float, headings, store="the store"):
    """A rare-event store's limiting Hs per relative heading at peak period ``Tp`` (its ``isee_limits``; a Tp
    or heading the campaign held fixed is read from its inputs) as the row of its incident definition in a
    sensitivity table (:class:`boatland.freqdomain.sensitivity.ExtraLimit`); None without a case there."""
    import math

    from boatland.freqdomain.sensitivity import ExtraLimit

    lim = data.get("isee_limits")
    if lim is None or lim.size == 0:
        return None
    fixed = json.loads(data["header"].get("inputs") or "{}")

    def value(row, key):                         # an axis of the campaign, else what it held fixed
        col = f"axis: {key}"
        return float(row[col]) if col in lim.dtype.names else fixed.get(key.split(".")[-1])
    found = {}
    for row in lim:
        tp, b = value(row, "sea.Tp"), value(row, "sea.relative_direction_deg")
        if tp is not None and b is not None and math.isclose(tp, Tp, rel_tol=1e-6):
            found.update({float(x): float(row["limiting Hs"]) for x in headings
                          if abs((b - x + 180) % 360 - 180) < 1e-6})
    if not found:
        return None
    name = data["plan"].get("name", "")
    return ExtraLimit(label=f"{lim['incident'][0].decode()} (time domain)", limits=found, short=f"ISEE {name}",
                      source=f"campaign {name!r} ({store}): the time domain's limiting Hs by importance sampling, "
                             "its isee_limits")


def store_sensitivity(data: dict, store="the store"):
    """What moves the limit of the campaign's base, as the campaign computed it (``/sensitivity``,
    :func:`boatland.campaign.prepare.case_sensitivity`) — with, for a rare-event store whose incident is not
    the slip onset, its own limiting Hs per heading as the row of the incident definition (from the
    screening's onset to the time domain's limit for this incident, :func:`isee_limits_at`). None when the
    store has none."""
    from boatland.freqdomain.sensitivity import Sensitivity

    text = data.get("sensitivity")
    if not text:
        return None
    d = json.loads(text)
    if "unavailable" in d:
        return None
    study = Sensitivity.from_dict(d)
    lim = data.get("isee_limits")
    if lim is None or lim["incident"][0].decode() == "first slip":
        return study
    extra = isee_limits_at(data, study.Tp, study.beta_deg, Path(str(store)).name)
    return study if extra is None else study.with_extra(extra)


def _fmt(v) -> str:
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, (float, np.floating)):
        return "" if math.isnan(v) else ("inf" if math.isinf(v) else f"{v:.4g}")
    return str(v)


def _write_csv(rows: list[list], header: list[str], path: Path) -> Path:
    with open(path, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows([[_fmt(v) for v in r] for r in rows])
    return path


def _write_md(rows: list[list[str]], header: list[str], path: Path, title: str, notes: str = "") -> Path:
    lines = [f"# {title}", "", "| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    if notes:
        lines += ["", notes]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _decision_csv(dec: Decision, path: Path) -> Path:
    """One row per cell (long form, for spreadsheets); every P column names its incident."""
    keys = list(dec.sections[0].fixed) if dec.sections else []
    methods = sorted({m for s in dec.sections for c in s.cells.values() for m in c.others})
    header = [axis_label(k) for k in keys] + [axis_label(HS_KEY)] + [axis_label(k) for k in dec.column_keys]
    inc = dec.incident
    header += ["trials", f"incidents ({inc})", f"P({inc})", f"P({inc}) lo", f"P({inc}) hi"]
    # The screening's column only in the table of the incident it predicts (the onset): a column
    # "screening P(first slip)" in a sheet about "slip > 0.1 m" would still be read, rows away from its
    # header, as that incident's prediction; cases.csv keeps it for every case, named.
    screening = dec.screening_beside
    if screening:
        header.append(f"screening P({ONSET}) (frequency domain)")
    for m in methods:
        header += [f"{m}: P({inc})", f"{m}: P({inc}) lo", f"{m}: P({inc}) hi"]
    rows = []
    for s in dec.sections:
        for (r, c), cell in sorted(s.cells.items()):
            row = [*s.fixed.values(), r, *c, cell.n, cell.k, cell.p, cell.lo, cell.hi]
            row += [cell.screening] if screening else []
            for m in methods:
                row += list(cell.others.get(m, (math.nan,) * 3))
            rows.append(row)
    return _write_csv(rows, header, path)


def _mean_text(m, lo, hi) -> str:
    if not math.isfinite(lo):
        return "–"
    if math.isinf(m):
        return f"none (mean ≥ {lo:.0f} s)"
    return f"{m:.0f} s [{lo:.0f}, {hi:.0f}]" if math.isfinite(hi) else f"{m:.0f} s [{lo:.0f}, –]"


def _cases_tables(stats, names, axes, dec: Decision, out):
    """``cases.csv`` with every column (raw names, for programs) and a readable ``cases.md``; the
    screening's P is named by the incident it predicts, first slip (in ``cases.md`` right after the
    time domain's P(first slip))."""
    header = ["case", "label", "trials", "failed", f"screening: P({ONSET}) (frequency domain)", "screening: note"]
    header += [axis_label(a) for a in axes]
    for n in names:
        header += [f"{n}: count", f"{n}: P", f"{n}: P lo", f"{n}: P hi", f"{n}: mean time [s]",
                   f"{n}: mean lo", f"{n}: mean hi"]
    cols = ["case", "label", "trials", "failed", "screening: P(slip)", "screening: note"] + [f"axis: {a}" for a in axes]
    cols += [f"{n}: {k}" for n in names for k in ("count", "P", "P lo", "P hi", "mean time", "mean lo", "mean hi")]
    files = [_write_csv([[r[c] for c in cols] for r in stats], header, out / "cases.csv")]
    p_head = [f"P({n})" for n in names]
    at = names.index(ONSET) + 1 if ONSET in names else len(names)     # the screening right after its incident
    md_head = ["case", *[axis_label(a) for a in axes], "trials", *p_head[:at], f"screening P({ONSET})",
               *p_head[at:], f"mean time to {dec.incident}"]
    rows = []
    for r in stats:
        ok = int(r["trials"]) - int(r["failed"])
        row = [str(int(r["case"])), *[value_text(a, float(r[f"axis: {a}"]), short=True) for a in axes],
               f"{ok}" + (f" (+{int(r['failed'])} failed)" if r["failed"] else "")]
        ps = [f"{int(r[f'{n}: count'])}/{ok} = {p_text(r[f'{n}: P'])} [{p_text(r[f'{n}: P lo'])}, "
              f"{p_text(r[f'{n}: P hi'])}]"
              if ok else "–" for n in names]
        fd = float(r["screening: P(slip)"])
        row += [*ps[:at], p_text(fd) if math.isfinite(fd) else (_fmt(r["screening: note"]) or "–"), *ps[at:]]
        i = dec.incident
        row.append(_mean_text(float(r[f"{i}: mean time"]), float(r[f"{i}: mean lo"]), float(r[f"{i}: mean hi"])))
        rows.append(row)
    files.append(_write_md(rows, md_head, out / "cases.md",
                           f"{dec.campaign}: every case — P(incident within the access) [Clopper–Pearson 95 %], "
                           f"mean time to {dec.incident} [χ² 95 %]",
                           "; ".join(t for t in (fixed_text(dec.inputs, axes),
                                                 (f"screening: the frequency-domain screening's P({ONSET} within "
                                                  "the access) — the slip onset, what it predicts")) if t)))
    return files


def _limiting_tables(dec: Decision, out):
    keys = list(dec.sections[0].fixed) if dec.sections else []
    header = [axis_label(k) for k in keys] + [axis_label(k) for k in dec.column_keys]
    header_csv = header + ["limiting Hs [m]", "lower [m]", "upper [m]", "estimate is", "lower is", "upper is"]
    rows_csv, rows_md = [], []
    for s in dec.sections:
        for c, lim in s.limits.items():
            rows_csv.append([*s.fixed.values(), *c, lim.estimate.value, lim.lower.value, lim.upper.value,
                             lim.estimate.where, lim.lower.where, lim.upper.where])
            rows_md.append([*(value_text(k, v, short=True) for k, v in s.fixed.items()),
                            *(value_text(k, v, short=True) for k, v in zip(dec.column_keys, c)), lim.text()])
    files = [_write_csv(rows_csv, header_csv, out / "limiting_hs.csv")]
    files.append(_write_md(rows_md, header + [f"limiting Hs [m] at P({dec.incident}) = {dec.target:g}"],
                           out / "limiting_hs.md",
                           f"{dec.campaign}: limiting Hs — P({dec.incident} within the access) = {dec.target:g}",
                           "Linear between the swept Hs; the interval is where the Clopper–Pearson 95 % bounds of P "
                           "reach the target; \"< x\": P is at or above the target already at the lowest swept Hs x; "
                           "\"> x\": it never reaches it up to the highest x. " + dec.advice() + "."))
    return files


# ------------------------------------------------------------------------------------------------ figures
def _source(campaign: str, inputs: dict) -> str:
    """What a figure was made from, for its title: the campaign, its scenario and vessel."""
    made = ", ".join(str(inputs[k]) for k in ("scenario", "vessel") if inputs.get(k))
    return f"{campaign} ({made})" if made else campaign


def _title(dec: Decision, what: str) -> str:
    fixed = fixed_text(dec.inputs, dec.axes)
    head = f"{_source(dec.campaign, dec.inputs)}:"
    sep = " " if len(head) + len(what) < 70 else "\n"          # a long title on lines of its own
    return f"{head}{sep}{what}" + (f"\n{fixed}" if fixed else "")


def figure_p_vs_hs(dec: Decision):
    """P(incident within the access) against Hs with Clopper–Pearson intervals, one line per section × Tp ×
    heading (and, when the incident is first slip — the onset the screening predicts — the screening's P,
    dashed); returns the Figure."""
    from boatland.plotstyle import pyplot

    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 5.4), layout="constrained")
    k = 0
    for s in dec.sections:
        for c in s.columns:
            got = [(r, s.cells[(r, c)]) for r in s.rows if (r, c) in s.cells and s.cells[(r, c)].n > 0]
            if not got:
                continue
            hs = np.array([r for r, _ in got])
            p = np.array([x.p for _, x in got])
            lo = np.array([x.lo for _, x in got])
            hi = np.array([x.hi for _, x in got])
            fd = np.array([x.screening for _, x in got])
            label = ", ".join(t for t in (s.title() if len(dec.sections) > 1 else "", s.column_text(c)) if t)
            color = f"C{k % 10}"
            ax.errorbar(hs + 0.004 * k, p, yerr=[p - lo, hi - p], marker="o", capsize=3, color=color,
                        label=f"{label}: Monte Carlo" if label else "Monte Carlo")
            if dec.screening_beside and np.isfinite(fd).any():
                ax.plot(hs, fd, ls="--", marker="x", color=color, lw=1,
                        label=f"{label}: screening" if label else "screening (frequency domain)")
            k += 1
    ax.axhline(dec.target, color="0.4", ls=":", lw=1, label=f"target P = {dec.target:g}")
    what = f"P({dec.incident}) with {100 * dec.confidence:g} % intervals"
    if not dec.screening_beside:
        what += f" (time domain; the screening predicts {ONSET} only)"
    ax.set(xlabel="Hs [m]", ylabel=f"P({dec.incident} within the access) [-]", ylim=(-0.02, 1.02),
           title=_title(dec, what))
    ax.title.set_fontsize(9)
    ax.grid(alpha=0.3)
    fig.legend(fontsize=7, loc="outside lower center", ncol=2)
    return fig


def figure_limiting_polar(dec: Decision):
    """Limiting Hs [m] against the heading (bow up, :mod:`boatland.plotstyle`), one line per Tp (and
    section), its interval shaded; "<"/">" ends of the sweep drawn as open triangles; returns the Figure."""
    from boatland.plotstyle import POLAR_NOTE, heading_polar, pyplot

    plt = pyplot()
    dkey = next((k for k in DIR_KEYS if k in dec.axes), None)
    fig = plt.figure(figsize=(6.2, 6.4), constrained_layout=True)
    ax = fig.add_subplot(projection="polar")
    k = 0
    for s in dec.sections:
        groups: dict[tuple, list] = {}
        for c in s.columns:
            if c not in s.limits:
                continue
            rest = tuple(v for key, v in zip(s.column_keys, c) if key != dkey)
            d = dict(zip(s.column_keys, c)).get(dkey)
            groups.setdefault(rest, []).append((d, s.limits[c]))
        for rest, pts in groups.items():
            pts.sort(key=lambda x: x[0])
            th = np.radians([d for d, _ in pts])
            est = np.array([lim.estimate.value for _, lim in pts])
            lo = np.array([lim.lower.value for _, lim in pts])
            hi = np.array([lim.upper.value for _, lim in pts])
            color = f"C{k % 10}"
            keys = [key for key in s.column_keys if key != dkey]
            label = ", ".join([*(value_text(kk, v) for kk, v in zip(keys, rest)),
                               *((s.title(),) if len(dec.sections) > 1 else ())]) or "limiting Hs"
            ax.plot(th, est, marker="o", color=color, label=label)
            if len(th) > 1:
                ax.fill_between(th, lo, hi, color=color, alpha=0.15, lw=0)
            for t, (_, lim) in zip(th, pts):
                if lim.estimate.where != "inside":
                    ax.plot([t], [lim.estimate.value], marker="v" if lim.estimate.where == "below" else "^",
                            ms=9, mfc="white", color=color)
            k += 1
    heading_polar(ax, rlabel="limiting Hs [m]")
    ax.set_title(_title(dec, f"limiting Hs [m] at P({dec.incident}) = {dec.target:g}") + f"\n{POLAR_NOTE}\n"
                 f"band: {100 * dec.confidence:g} % interval; ▽ / △: below / above the swept Hs", fontsize=8)
    if k:
        ax.legend(fontsize=7, loc="lower left", bbox_to_anchor=(-0.12, -0.12))
    return fig


def figure_time_to_incident(data: dict, dec: Decision):
    """Empirical distribution of the time to the first incident per case; returns the Figure."""
    from boatland.plotstyle import pyplot

    plt = pyplot()
    stats, trials = data["stats"], data["trials"]
    fig, ax = plt.subplots(figsize=(7.5, 4.8), constrained_layout=True)
    col = INCIDENT_PREFIX + dec.incident
    axes = dec.axes
    drawn = 0
    for r in stats:
        t = trials[col][(trials["case"] == r["case"]) & completed(trials)]
        if not np.isfinite(t).any():
            continue
        ts = np.sort(t[np.isfinite(t)])
        label = ", ".join(value_text(a, float(r[f"axis: {a}"])) for a in axes) or "all"
        ax.step(np.r_[0, ts], np.arange(ts.size + 1) / t.size, where="post", label=label)
        drawn += 1
    ax.set(xlabel="time from the waves' full height to the first incident [s]", ylabel="fraction of trials [-]", ylim=(0, 1.02),
           title=_title(dec, f"time to {dec.incident} (empirical; trials without one never reach the top)"))
    ax.title.set_fontsize(9)
    ax.grid(alpha=0.3)
    if 0 < drawn <= 12:
        ax.legend(fontsize=7)
    if not drawn:
        ax.text(0.5, 0.5, f"no trial had the incident {dec.incident}", transform=ax.transAxes, ha="center",
                va="center", fontsize=9, color="0.3")
    return fig


def _figures(data, dec: Decision, out):
    from boatland.plotstyle import save_figure

    files = []
    if HS_KEY in dec.axes:
        files.append(save_figure(figure_p_vs_hs(dec), out / "p_vs_hs.png"))
        if any(k in dec.axes for k in DIR_KEYS):
            files.append(save_figure(figure_limiting_polar(dec), out / "limiting_hs_polar.png"))
    files.append(save_figure(figure_time_to_incident(data, dec), out / "time_to_incident.png"))
    return files


def _save(fig, path: Path, tight: bool = True) -> Path:
    """Save and close ``fig``; ``tight``: lay it out first (not for a figure whose axes are placed by hand,
    which matplotlib would warn about)."""
    from boatland.plotstyle import save_figure

    if tight:
        fig.tight_layout()
    return save_figure(fig, path)


def _write_tables(rows: list[list], header: list[str], out: Path, stem: str, title: str) -> list[Path]:
    return [_write_csv(rows, header, out / f"{stem}.csv"),
            _write_md([[_fmt(v) for v in r] for r in rows], header, out / f"{stem}.md", title)]


# ---------------------------------------------------------------------------------------- isee
def isee_incident(data: dict, incident: str | None = None) -> str:
    """The incident a rare-event store's report is about: ``incident``, else the campaign's ``[isee]
    incident`` (one clear error for a name the store does not hold)."""
    names = data["header"]["incidents"].split("\n")
    settings = json.loads(data["header"].get("isee", "{}"))
    inc = incident or settings.get("incident", ONSET)
    if inc not in names:
        raise BoatlandInputError(f"incident {inc!r} is not one of the campaign's: {', '.join(names)}")
    return inc


def isee_linear(incident: str) -> str:
    """The linear model's estimate an ISEE limit of ``incident`` is fitted beside (:mod:`boatland.campaign.isee`)."""
    return "linear first slip" if incident == ONSET else "linear first incident"


def _isee_report(data, out: Path, incident: str | None, figures: bool) -> tuple[str, list[Path]]:
    """The ISEE tables and figures; returns the report's incident and the files. Every column of P names
    the incident it is of: the campaign's, the linear model's, the screening's (the onset)."""
    runs, plan = data["stats"], data["plan"]
    inc = isee_incident(data, incident)
    head = ["case", "label", "Hs [m]", "samples", "failed", f"P({inc})", f"CoV ({inc})", f"P({inc}) lo",
            f"P({inc}) hi", "linear P(first slip) (circle)", "linear P(first slip) (square: the screening's margins)",
            "sampling domain P", "largest elementary P (linear first incident)", "Rice bound (linear first incident)",
            f"screening P({ONSET}) Rayleigh", f"screening P({ONSET}) Rice", f"screening P({ONSET}) Vanmarcke",
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
        lin = isee_linear(inc)
        head = ["case", "label", *axes, f"limiting Hs [m] ({inc})", "lo", "hi", f"linear model [m] ({lin})", "lo",
                "hi", f"screening Rayleigh [m] ({ONSET})", f"screening Rice [m] ({ONSET})",
                f"screening Vanmarcke [m] ({ONSET})", "levels", "samples"]
        rows = [[L["case"], L["label"], *[L[f"axis: {a}"] for a in axes], L["limiting Hs"], L["limiting Hs lo"],
                 L["limiting Hs hi"], L["linear limiting Hs"], L["linear limiting Hs lo"], L["linear limiting Hs hi"],
                 L["screening rayleigh Hs"], L["screening rice Hs"], L["screening vanmarcke Hs"], L["levels"],
                 L["samples"]] for L in lim]
        acc = float(lim["accept"][0]) if lim.size else math.nan
        files += _write_tables(rows, head, out, "isee_limits",
                               f"Limiting Hs at P({inc} within the access) = {acc:g}: time domain by ISEE (95 % "
                               "interval), the linear model, the frequency-domain screening")
    if figures:
        files += _isee_figures(runs, lim, plan, inc, out,
                               _source(data["header"].get("campaign", ""), inputs_from_header(data["header"])))
    return inc, files


def _isee_figures(runs, lim, plan, inc, out, source: str):
    from boatland.plotstyle import heading_polar, pyplot

    plt = pyplot()

    files = []
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for c in np.unique(runs["case"]):
        r = runs[runs["case"] == c]
        r = r[np.argsort(r["hs"])]
        p, lo, hi = r[f"{inc}: P"], r[f"{inc}: P lo"], r[f"{inc}: P hi"]
        ax.errorbar(r["hs"], p, yerr=[np.maximum(p - lo, 0), np.maximum(hi - p, 0)], marker="o", capsize=3,
                    label=_fmt(r["label"][0]) or "base")
    ax.set(xlabel="Hs [m]", ylabel=f"P({inc} within the access)", yscale="log",
           title=f"{source}: ISEE, time domain on the sampled seas (95 %)")
    ax.grid(alpha=0.3, which="both")
    if runs.size <= 40:
        ax.legend(fontsize=7)
    files.append(_save(fig, out / "p_vs_hs.png"))
    axes = list(plan["axes"])
    dkey = next((k for k in DIR_KEYS if k in axes), None)
    if lim is not None and dkey is not None:
        tkey = next((k for k in TP_KEYS if k in axes), None)
        fig = plt.figure(figsize=(6, 7.2))
        ax = fig.add_axes((0.12, 0.26, 0.76, 0.63), projection="polar")   # the legend below, clear of "0° following"
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
            stat = DEFAULT_STATISTICS            # the screening's statistic, as boatland campaign prints it
            ax.plot(th, sel[f"screening {stat} Hs"], ls="--", color=colour, lw=1,
                    label=f"{label}: screening ({stat})" if inc == ONSET else f"{label}: screening ({ONSET}, {stat})")
        heading_polar(ax)
        acc = float(lim["accept"][0])
        ax.set_title(f"{source}: limiting Hs [m] at P({inc}) = {acc:g} per access\n(heading relative to the bow)",
                     fontsize=9)
        fig.legend(*ax.get_legend_handles_labels(), fontsize=6, loc="lower center", ncol=2, frameon=False)
        files.append(_save(fig, out / "limiting_hs_polar.png", tight=False))   # axes placed by hand
    return files
