"""The campaign report's one page, ``report.html``: what a planner decides from, in one file that
opens offline and reads on a phone.

Contents, in this order:

1. the campaign's name and provenance — the store (file, when it was last written, the boatland
   version that wrote it, the campaign's digest) and when and by which version the page was written;
2. the inputs — vessel, base scenario, sea, push, μ_s/μ_k, fender shear stiffness, seeds, the access,
   the swept axes (what the store's header and plan hold) and the campaign file itself (folded);
3. the incident, its name exactly as stored, and the accepted risk in words
   (:func:`boatland.freqdomain.statistics.risk_in_words`);
4. the decision table, the same numbers as ``decision.md`` (:class:`boatland.campaign.decision.Decision`)
   — for a rare-event (ISEE) store the limiting Hs per case with its interval and the per-run estimates;
5. sensitivity: what moves the limit — the study given, by default the campaign's own, computed beside its
   trials and kept in the store (:func:`boatland.campaign.report.store_sensitivity`) — as a table and a
   tornado figure (:func:`sensitivity_items`), or how to get it;
6. the report's figures.

Like with like: the frequency-domain screening predicts slip onsets, so its figures stand beside the
time domain's only when the incident is "first slip" (:data:`boatland.campaign.decision.ONSET`); every
column names the incident it is of.

Self-contained: figures are embedded as ``data:image/png;base64`` URIs; one inline ``<style>``, system
fonts, no script, no link, no external URL of any kind. Tables scroll sideways inside their own box;
the body has a maximum width. Every text from the store is escaped (:func:`html.escape`).

The sensitivity hook. :func:`boatland.campaign.report.write_report` takes ``sensitivity=``: the result of
:func:`boatland.freqdomain.sensitivity.sensitivity` (``boatland screen --sensitivity``) as it is, or rows —
each a :class:`SensitivityItem` or a mapping with its keys (``factor``, ``range_text``, ``source``, ``low``,
``high`` and optionally ``base``; the last three map a heading's label to the limiting Hs [m] with the
factor at the low / high end of its range, and at the base). This module computes nothing: it shows them.
"""

from __future__ import annotations

import base64
import datetime as _dt
import json
import math
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from html import escape
from pathlib import Path

from boatland import __version__
from boatland.atomic import atomic_path
from boatland.campaign.decision import ONSET, SCREENING_NOTE, Decision
from boatland.campaign.labels import (
    axis_label,
    fixed_text,
    inputs_from_header,
    value_text,
)
from boatland.errors import BoatlandInputError
from boatland.freqdomain.statistics import (
    ACCEPT_PRESETS,
    ACCESS_DURATION,
    DEFAULT_STATISTICS,
    one_in,
    probability_text,
    risk_in_words,
)

__all__ = ["FIGURE_CAPTIONS", "TORNADO", "SensitivityItem", "figure_sensitivity", "isee_page", "monte_carlo_page",
           "risk_text", "sensitivity_items", "write_page"]

#: File name of the sensitivity study's tornado figure.
TORNADO = "sensitivity_tornado.png"

#: What each figure of the report shows (its caption on the page; ``{incident}``: the report's).
FIGURE_CAPTIONS = {
    "p_vs_hs.png": "P({incident} within the access) against Hs with its 95 % intervals",
    "limiting_hs_polar.png": "Limiting Hs at the accepted P({incident}) against the heading (180° head seas at "
                             "the top)",
    "time_to_incident.png": "Time from the waves' full height to the incident ({incident}), per case (empirical)",
    TORNADO: "Limiting Hs with each factor at the low and high end of its range",
}

_STYLE = """
:root { color-scheme: light dark; }
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, sans-serif;
       line-height: 1.45; max-width: 60rem; margin: 0 auto; padding: 0 1rem 3rem; }
h1 { font-size: 1.5rem; margin-bottom: 0.2rem; } h2 { font-size: 1.2rem; margin-top: 2rem; }
h3 { font-size: 1rem; }
nav a { margin-right: 0.8rem; white-space: nowrap; }
.scroll { overflow-x: auto; -webkit-overflow-scrolling: touch; margin: 0.5rem 0; max-width: 100%; }
table { border-collapse: collapse; font-size: 0.9rem; }
th, td { border: 1px solid rgba(128, 128, 128, 0.45); padding: 0.25rem 0.5rem; text-align: left;
         vertical-align: top; white-space: nowrap; }
tbody th { position: sticky; left: 0; background: Canvas; }
thead th { background: rgba(128, 128, 128, 0.15); }
tr.limit th, tr.limit td { font-weight: 600; border-top: 2px solid rgba(128, 128, 128, 0.8); }
dl.kv { display: grid; grid-template-columns: max-content 1fr; gap: 0.15rem 1rem; margin: 0.5rem 0; }
dl.kv dt { font-weight: 600; } dl.kv dd { margin: 0; overflow-wrap: anywhere; }
.note { opacity: 0.8; font-size: 0.9rem; }
.risk { font-size: 1.1rem; }
figure { margin: 1.2rem 0; } figcaption { font-size: 0.9rem; opacity: 0.8; }
img { max-width: 100%; height: auto; background: #fff; }
pre { overflow-x: auto; font-size: 0.8rem; }
code, pre { font-family: ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; }
"""


# ------------------------------------------------------------------------------------------ sensitivity
@dataclass(frozen=True)
class SensitivityItem:
    """One uncertain input of a sensitivity study and how far the limiting Hs moves across its range —
    one row of the page's sensitivity table.

    Attributes
    ----------
    factor : str
        The input, as a reader names it ("μ_s", "push", "fender shear stiffness").
    range_text : str
        Its range in words with units ("0.5 – 0.8", "100 kN – 300 kN").
    source : str
        Where the range comes from ("Wu 2014 tests", "operator's logs").
    low, high : mapping of str to float
        Heading label ("head seas (180°)") → limiting Hs [m] with the factor at the low / high end of its
        range (NaN: not known; inf: above the screening's largest Hs).
    base : mapping of str to float, optional
        Heading label → limiting Hs [m] at the base (every factor at its base value).
    """

    factor: str
    range_text: str
    source: str
    low: Mapping[str, float] = field(default_factory=dict)
    high: Mapping[str, float] = field(default_factory=dict)
    base: Mapping[str, float] = field(default_factory=dict)

    def headings(self) -> list[str]:
        """The heading labels of the row, in their order."""
        return list(dict.fromkeys([*self.base, *self.low, *self.high]))


def _is_study(obj) -> bool:
    """A :class:`boatland.freqdomain.sensitivity.Sensitivity` (its rows, headings and base limits)."""
    return all(hasattr(obj, a) for a in ("rows", "beta_deg", "base"))


def sensitivity_items(sensitivity) -> list[SensitivityItem] | None:
    """The rows of a sensitivity study as :class:`SensitivityItem` (None when there is none).

    Parameters
    ----------
    sensitivity : Sensitivity, or sequence of SensitivityItem or mapping, or None
        A :class:`boatland.freqdomain.sensitivity.Sensitivity` (``boatland screen --sensitivity``'s result:
        per row ``label``, ``range_text``, ``short``, and ``low``/``high`` per heading of its ``beta_deg``),
        or rows: a mapping holds the keys ``factor``, ``range_text`` (or ``range``), ``source``, ``low``,
        ``high`` (and optionally ``base``), each of the last a mapping heading label → limiting Hs [m].

    Raises
    ------
    BoatlandInputError
        A row that is neither, or lacks a key (one line naming it).
    """
    if sensitivity is None:
        return None
    if _is_study(sensitivity):
        heads = [value_text("sea.relative_direction_deg", float(b)) for b in sensitivity.beta_deg]
        base = dict(zip(heads, map(float, sensitivity.base)))
        return [SensitivityItem(factor=r.label, range_text=r.range_text, source=getattr(r, "short", "") or r.source,
                                low=dict(zip(heads, map(float, r.low))), high=dict(zip(heads, map(float, r.high))),
                                base=base) for r in sensitivity.rows]
    out = []
    for i, r in enumerate(sensitivity):
        if isinstance(r, SensitivityItem):
            out.append(r)
            continue
        if not isinstance(r, Mapping):
            raise BoatlandInputError(f"sensitivity row {i}: a SensitivityItem or a mapping, not {type(r).__name__}")
        try:
            out.append(SensitivityItem(
                factor=str(r["factor"]), range_text=str(r["range_text"] if "range_text" in r else r["range"]),
                source=str(r["source"]), **{k: {str(h): float(v) for h, v in dict(r.get(k) or {}).items()}
                                            for k in ("low", "high", "base")}))
        except (KeyError, TypeError, ValueError) as exc:
            raise BoatlandInputError(f"sensitivity row {i}: needs factor, range_text, source, low and high "
                                     f"(heading → limiting Hs [m]); {type(exc).__name__}: {exc}") from None
    return out


def sensitivity_note(sensitivity) -> str:
    """What the limits of a sensitivity study are limits of, in words (a study of
    :mod:`boatland.freqdomain.sensitivity`: the screening's slip onset at its accepted risk, peak period,
    statistics and base; rows: as given)."""
    if _is_study(sensitivity):
        return (f"The frequency-domain screening's limiting Hs of slip onsets ({ONSET}) at "
                f"{risk_text(float(sensitivity.accept), float(sensitivity.access_duration))}, Tp "
                f"{float(sensitivity.Tp):g} s, {sensitivity.statistics} statistics, one factor at a time; base: "
                f"{sensitivity.base_text}. Rows computed elsewhere name their own incident.")
    return "Limiting Hs as given with the rows (their source says of which incident and at which risk)."


def _hs(v) -> str:
    v = float(v)
    return "–" if math.isnan(v) else ("none" if math.isinf(v) else f"{v:.2f}")


def figure_sensitivity(sensitivity, title: str = ""):
    """The tornado figure of a sensitivity study (``title`` above it, e.g. the campaign and its inputs);
    returns the Figure.

    A :class:`boatland.freqdomain.sensitivity.Sensitivity` is drawn by its own
    :func:`boatland.freqdomain.sensitivity.figure_tornado`; rows (:func:`sensitivity_items`) as one panel per
    heading, one bar per factor from the limit with the factor at one end of its range to the other (from
    the base where it is given), the widest swing on top.
    """
    if _is_study(sensitivity):
        from boatland.freqdomain.sensitivity import figure_tornado

        return figure_tornado(sensitivity, title=title)
    from matplotlib.lines import Line2D

    from boatland.plotstyle import pyplot

    items = sensitivity_items(sensitivity) or []
    plt = pyplot()
    headings = list(dict.fromkeys(h for r in items for h in r.headings())) or ["–"]
    fig, axes = plt.subplots(1, len(headings), figsize=(3.6 * len(headings) + 1.6, 0.45 * len(items) + 1.8),
                             sharey=True, squeeze=False, layout="constrained")

    def swing(r):
        v = [x for x in (r.low.get(headings[0], math.nan), r.high.get(headings[0], math.nan)) if not math.isnan(x)]
        return max(v) - min(v) if len(v) == 2 else -1.0       # inf (no limit at one end): the widest

    order = sorted(items, key=swing)                       # the widest last: drawn on top
    finite = [x for r in items for m in (r.low, r.high, r.base) for x in m.values() if math.isfinite(x)]
    top = 1.15 * max(finite, default=1.0)                  # where "no limit" (inf) ends are drawn
    for ax, h in zip(axes[0], headings):
        for k, r in enumerate(order):
            lo, hi, b = (min(r.low.get(h, math.nan), top), min(r.high.get(h, math.nan), top),
                         r.base.get(h, math.nan))
            ends = [x for x in (lo, hi, b) if math.isfinite(x)]
            if len(ends) >= 2:
                ax.barh(k, max(ends) - min(ends), left=min(ends), color="0.82", height=0.5)
            ax.plot([lo], [k], "o", color="C0")
            ax.plot([hi], [k], "s", color="C3")
            if math.isfinite(b):
                ax.plot([b, b], [k - 0.3, k + 0.3], color="k", lw=1.2)
        ax.set(title=h, xlabel="limiting Hs [m]", xlim=(0, top * 1.03), ylim=(-0.7, len(order) - 0.3))
        ax.title.set_fontsize(9)
        ax.grid(alpha=0.3, axis="x")
    axes[0][0].set_yticks(range(len(order)), [f"{r.factor}\n{r.range_text}" for r in order], fontsize=8)
    handles = [Line2D([], [], marker="o", color="C0", ls="", label="factor at its low end"),
               Line2D([], [], marker="s", color="C3", ls="", label="factor at its high end"),
               Line2D([], [], color="k", lw=1.2, label="base"),
               Line2D([], [], color="none", label=f"no limit: drawn at {top:.2f} m")]
    fig.legend(handles=handles, loc="outside lower center", ncol=4, fontsize=7, frameon=False)
    return fig


# ------------------------------------------------------------------------------------------ building blocks
def _e(v) -> str:
    if isinstance(v, bytes):
        v = v.decode()
    return escape(str(v), quote=True)


def _table(head: Sequence[str], rows: Sequence[Sequence], *, limit_last: bool = False,
           cell_attrs: Sequence[Sequence[str]] | None = None) -> str:
    """A table in its own sideways-scrolling box; the first column is a row heading. ``cell_attrs``:
    extra attributes per body cell (already escaped)."""
    out = ['<div class="scroll"><table>', "<thead><tr>" + "".join(f'<th scope="col">{_e(h)}</th>' for h in head)
           + "</tr></thead>", "<tbody>"]
    for i, row in enumerate(rows):
        cls = ' class="limit"' if limit_last and i == len(rows) - 1 else ""
        attrs = cell_attrs[i] if cell_attrs is not None else [""] * len(row)
        cells = [f'<th scope="row">{_e(row[0])}</th>'] + [f"<td{a}>{_e(v)}</td>" for v, a in zip(row[1:], attrs[1:])]
        out.append(f"<tr{cls}>" + "".join(cells) + "</tr>")
    out.append("</tbody></table></div>")
    return "\n".join(out)


def _dl(items: Sequence[tuple[str, str]]) -> str:
    return '<dl class="kv">' + "".join(f"<dt>{_e(k)}</dt><dd>{_e(v)}</dd>" for k, v in items if v not in (None, "")) \
        + "</dl>"


def _p(text: str, cls: str = "") -> str:
    return f'<p class="{cls}">{_e(text)}</p>' if cls else f"<p>{_e(text)}</p>"


def _incident_line(incident: str) -> str:
    return f'<p class="risk">Incident: <strong>{_e(incident)}</strong> (its name as the store holds it)</p>'


def _img(path: Path, caption: str) -> str:
    data = base64.b64encode(Path(path).read_bytes()).decode("ascii")
    return (f'<figure><img src="data:image/png;base64,{data}" alt="{_e(caption)}">'
            f"<figcaption>{_e(caption)} ({_e(Path(path).name)})</figcaption></figure>")


def _when(t: float) -> str:
    return _dt.datetime.fromtimestamp(t, _dt.UTC).strftime("%Y-%m-%d %H:%M UTC")


def _campaign_toml(header: dict) -> dict:
    try:
        return tomllib.loads(header.get("campaign_file", ""))
    except (tomllib.TOMLDecodeError, TypeError):
        return {}


def risk_text(p: float, access: float | None) -> str:
    """The accepted risk in words (:func:`~boatland.freqdomain.statistics.risk_in_words`) for an access
    of ``access`` seconds; without a known access, per access unnamed."""
    try:
        if access is not None and math.isfinite(access) and access > 0:
            return risk_in_words(p, access)
        return f"{one_in(p).replace('1 in', '1 access in')} ({probability_text(p)} per access)"
    except BoatlandInputError:
        return f"P = {p:g} per access"


def _document(title: str, sections: list[tuple[str, str, str]], header_html: str) -> str:
    nav = "<nav>" + "".join(f'<a href="#{sid}">{_e(name)}</a>' for sid, name, _ in sections) + "</nav>"
    body = "\n".join(f'<section id="{sid}"><h2>{_e(name)}</h2>\n{content}\n</section>' for sid, name, content in sections)
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
            f"<title>{_e(title)}</title>\n<style>{_STYLE}</style>\n</head>\n<body>\n<header>{header_html}</header>\n"
            f"{nav}\n{body}\n</body>\n</html>\n")


def _header(data: dict, store: Path | None, method: str, extra: Sequence[tuple[str, str]] = ()) -> str:
    header, plan = data["header"], data["plan"]
    name = str(header.get("campaign", plan.get("name", "campaign")))
    inputs = inputs_from_header(header)
    items = [("method", method)]
    if store is not None:
        items.append(("store", str(store)))
        if Path(store).exists():
            items.append(("store last written", _when(Path(store).stat().st_mtime)))
    now = _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")
    items += [("written by", f"boatland {header.get('boatland_version', plan.get('boatland', '?'))}"),
              ("campaign digest", str(header.get("campaign_digest", ""))[:16]), *extra,
              ("this page", f"{now}, boatland {__version__}")]
    desc = inputs.get("description") or ""
    return f"<h1>{_e(name)}</h1>" + (_p(desc, "note") if desc else "") + _dl(items)


def _inputs_section(data: dict, inputs: dict, extra: Sequence[tuple[str, str]] = (), *, seeds: bool = True) -> str:
    header, plan = data["header"], data["plan"]
    axes = dict(plan.get("axes") or {})
    swept = set(axes)
    items = [("vessel", inputs.get("vessel")), ("base scenario", inputs.get("scenario") or plan.get("scenario")),
             ("sea (base scenario)", inputs.get("sea"))]
    if inputs.get("Hs") is not None and "sea.Hs" not in swept:
        items.append(("Hs", f"{inputs['Hs']:g} m"))
    if inputs.get("Tp") is not None and "sea.Tp" not in swept:
        items.append(("Tp", f"{inputs['Tp']:g} s"))
    if inputs.get("relative_direction_deg") is not None and not swept & {"sea.relative_direction_deg",
                                                                          "sea.direction_deg"}:
        items.append(("heading", f"{inputs.get('heading', '')} ({inputs['relative_direction_deg']:g}°)"))
    if "thrust" in inputs:
        items.append(("push", "none" if inputs["thrust"] is None else f"{inputs['thrust'] / 1e3:g} kN"))
    if inputs.get("mu_s") is not None:
        mu_k = inputs.get("mu_k")
        items.append(("μ_s / μ_k", f"{inputs['mu_s']:g} / " + ("–" if mu_k is None else f"{mu_k:g}")))
    if "shear_stiffness" in inputs:
        k = inputs["shear_stiffness"]
        items.append(("fender shear stiffness", "rigid stick" if k is None else f"{k / 1e3:g} kN/m per contact"))
    for key, values in axes.items():
        items.append((f"swept: {axis_label(key)}", ", ".join(value_text(key, v, short=True) for v in values)))
    n_seeds = inputs.get("seeds", plan.get("seeds")) if seeds else None
    if n_seeds is not None:
        items.append(("seeds per case", str(n_seeds)))
    if plan.get("master_seed") is not None:
        items.append(("master seed", str(plan["master_seed"])))
    items += list(extra)
    if inputs.get("access") is not None:
        items.append(("access", f"{inputs['access']:g} s of full waves per trial"))
    items.append(("incidents counted", ", ".join(header["incidents"].split("\n"))))
    fixed = fixed_text(inputs, axes)
    text = _dl(items) + (_p(f"In one phrase: {fixed}.", "note") if fixed else "")
    if header.get("campaign_file"):
        text += f"<details><summary>campaign file</summary><pre>{_e(header['campaign_file'])}</pre></details>"
    return text


def _sensitivity_section(sensitivity, figures: Sequence[Path]) -> str:
    rows = sensitivity_items(sensitivity)
    if not rows:
        return _p("No sensitivity study was given. 'boatland screen --sensitivity' computes how far the limiting "
                  "Hs moves with each uncertain input (μ_s, push, fender stiffness, …) over its range; its rows "
                  "go to the report as write_report(..., sensitivity=rows).", "note")
    headings = list(dict.fromkeys(h for r in rows for h in r.headings()))
    head = ["factor", "range", "source"] + [f"limiting Hs [m] at low / high end: {h}" for h in headings]
    body = [[r.factor, r.range_text, r.source] + [f"{_hs(r.low.get(h, math.nan))} / {_hs(r.high.get(h, math.nan))}"
                                                 for h in headings] for r in rows]
    bases = {h: r.base[h] for r in rows for h in r.base}
    if bases:
        body.insert(0, ["base", "", ""] + [_hs(bases.get(h, math.nan)) for h in headings])
    text = _p(sensitivity_note(sensitivity), "note") + _table(head, body)
    tornado = [f for f in figures if Path(f).name == TORNADO]
    return text + "".join(_img(f, FIGURE_CAPTIONS[TORNADO]) for f in tornado)


def _figures_section(figures: Sequence[Path], incident: str) -> str:
    figs = [f for f in figures if Path(f).name != TORNADO]
    if not figs:
        return _p("No figures were drawn (figures=False).", "note")
    return "\n".join(_img(f, FIGURE_CAPTIONS.get(Path(f).name, Path(f).stem.replace("_", " ")).format(
        incident=incident)) for f in figs)


# ------------------------------------------------------------------------------------------ pages
def monte_carlo_page(data: dict, dec: Decision, *, store: Path | None = None, figures: Sequence[Path] = (),
                     sensitivity=None) -> str:
    """The page of a Monte Carlo campaign (module docstring), as text.

    Parameters
    ----------
    data : dict
        The store as :func:`boatland.campaign.report.read_store` gives it.
    dec : Decision
        Its decision table (:func:`boatland.campaign.decision.decision`): incident, target, cells.
    store : Path, optional
        The store's file (provenance).
    figures : sequence of Path
        PNG files to embed (the tornado, ``sensitivity_tornado.png``, in the sensitivity section).
    sensitivity : optional
        A sensitivity study or its rows, as :func:`sensitivity_items` takes them.

    Returns
    -------
    str
        The HTML document.
    """
    inputs = dec.inputs
    access = inputs.get("access")
    n = len(data["trials"])
    head = _header(data, store, "Monte Carlo (time domain, N seeds per case)",
                   [("trials", f"{n} ({dec.seeds} seeds per case)")])
    risk = [_incident_line(dec.incident),
            _p(f"Accepted risk: {risk_text(dec.target, access)} — the limiting Hs is where P({dec.incident} "
               "within the access) reaches it.", "risk")]
    if not math.isclose(dec.target, ACCEPT_PRESETS["best"]):
        risk.append(_p(f"For comparison, Grøtting (2015)'s best estimate of the accepted risk: "
                       f"{risk_in_words('best', ACCESS_DURATION)}; the target is boatland report's --target.",
                       "note"))
    if not dec.screening_beside:
        risk.append(_p(f"Time-domain figures only: {SCREENING_NOTE} (boatland report --incident \"{ONSET}\").",
                       "note"))
    tables = [_p(f"{dec.axes_text()}; {dec.legend()}.", "note")]
    for s in dec.sections:
        if len(dec.sections) > 1:
            tables.append(f"<h3>{_e(s.title())}</h3>")
        tables.append(_decision_table(dec, s))
    tables.append(_p(f"Limiting Hs: where P reaches {dec.target:g}, linear between the swept Hs; its interval is "
                     "where the Clopper–Pearson bounds of P reach it; \"<\" / \">\": it does not cross inside the "
                     "sweep.", "note"))
    tables.append(_p(dec.advice() + ".", "note"))
    sections = [("inputs", "Inputs", _inputs_section(data, inputs)),
                ("risk", "Incident and accepted risk", "\n".join(risk)),
                ("decision", "Decision table", "\n".join(tables)),
                ("sensitivity", "Sensitivity", _sensitivity_section(sensitivity, figures)),
                ("figures", "Figures", _figures_section(figures, dec.incident))]
    return _document(f"{dec.campaign}: P({dec.incident})", sections, head)


def _decision_table(dec: Decision, s) -> str:
    """One section of the decision table: the cells' texts of ``decision.md``, each ``<td>`` with its case
    (``data-case``) and counts (``title``)."""
    head = [axis_label("sea.Hs") if "sea.Hs" in dec.axes else "case"] + [s.column_text(c) for c in s.columns]
    rows, attrs = [], []
    for r in s.rows:
        row, at = [f"{r:g}" if isinstance(r, float) else str(r)], [""]
        for c in s.columns:
            cell = s.cells.get((r, c))
            row.append(cell.text(screening=dec.screening_beside) if cell is not None else "–")
            at.append(f' data-case="{cell.case}" title="{cell.k} of {cell.n} trials"' if cell is not None else "")
        rows.append(row)
        attrs.append(at)
    if s.limits:
        rows.append([f"limiting Hs at P = {dec.target:g} ({one_in(dec.target)})"] + [s.limits[c].text() if c in s.limits else "–"
                                                              for c in s.columns])
        attrs.append([""] * len(rows[-1]))
    return _table(head, rows, limit_last=bool(s.limits), cell_attrs=attrs)


def _g(v, digits: int = 3) -> str:
    v = float(v)
    return "–" if not math.isfinite(v) else f"{v:.{digits}g}"


def isee_page(data: dict, incident: str, *, store: Path | None = None, figures: Sequence[Path] = (),
              sensitivity=None) -> str:
    """The page of a rare-event (ISEE) campaign, as text: the per-case limiting Hs with its interval and
    the per-run estimates instead of the decision table (module docstring).

    Parameters
    ----------
    data : dict
        The store as :func:`boatland.campaign.report.read_store` gives it (``method = "isee"``).
    incident : str
        The incident of the report (:func:`boatland.campaign.report.isee_incident`).
    store, figures, sensitivity
        As :func:`monte_carlo_page`.

    Returns
    -------
    str
        The HTML document.
    """
    header, plan, runs = data["header"], data["plan"], data["stats"]
    settings = json.loads(header.get("isee", "{}") or "{}")
    toml = _campaign_toml(header)
    access = toml.get("access", toml.get("duration"))   # "duration": the older name of the access
    lim = data.get("isee_limits")
    accept = float(lim["accept"][0]) if lim is not None and lim.size else settings.get("accept")
    onset = incident == ONSET
    lin = "linear first slip" if onset else "linear first incident"
    stat = DEFAULT_STATISTICS           # the screening's statistic, as boatland campaign prints it
    head = _header(data, store, "rare-event sampling (ISEE, time domain on importance-sampled seas)",
                   [("samples", str(len(data["trials"]))), ("runs", str(len(runs)))])
    how = (f"target CoV {settings.get('target_cov', '?')}, batches of {settings.get('batch', '?')}, "
           f"{settings.get('min_samples', '?')}–{settings.get('max_samples', '?')} samples per run, "
           f"up to {settings.get('levels', '?')} Hs levels, settle {settings.get('settle', '?')} s")
    extra = [("ISEE", how)]
    if access is not None and "inputs" not in data["header"]:      # else the inputs say it
        extra.append(("access", f"{float(access):g} s of full waves per sample"))
    risk = [_incident_line(incident)]
    if accept is not None:
        risk.append(_p(f"Accepted risk: {risk_text(float(accept), None if access is None else float(access))} — "
                       f"the limiting Hs is where P({incident} within the access) reaches it.", "risk"))
    else:
        risk.append(_p("No accepted risk was set ([isee] accept): the runs' estimates only, no limiting Hs.", "risk"))
    if not onset:
        risk.append(_p(f"Time-domain figures only: {SCREENING_NOTE}; the linear model's likewise.", "note"))
    axes = list(plan.get("axes") or {})
    parts = []
    if lim is not None and lim.size:
        hd = ["case", *[axis_label(a) for a in axes], f"limiting Hs [m] ({incident}) [95 %]"]
        if onset:
            hd += [f"linear model [m] ({lin}) [95 %]", f"screening [m] ({ONSET}, {stat})"]
        hd += ["levels", "samples"]
        rows = []
        for L in lim:
            found = math.isfinite(float(L["limiting Hs"]))
            row = [str(int(L["case"])), *[value_text(a, float(L[f"axis: {a}"]), short=True) for a in axes],
                   f"{_g(L['limiting Hs'], 4)} [{_g(L['limiting Hs lo'], 4)}, {_g(L['limiting Hs hi'], 4)}]"
                   if found else "not found (no estimate reached it at the levels run)"]
            if onset:
                linear = (f"{_g(L['linear limiting Hs'], 4)} [{_g(L['linear limiting Hs lo'], 4)}, "
                          f"{_g(L['linear limiting Hs hi'], 4)}]")
                row += [linear, _g(L[f"screening {stat} Hs"], 4)]
            rows.append(row + [str(int(L["levels"])), str(int(L["samples"]))])
        parts += [f"<h3>Limiting Hs at P({_e(incident)}) = {_e(f'{accept:g}')} per access</h3>", _table(hd, rows)]
    hd = ["case", *[axis_label(a) for a in axes], "Hs [m]", "samples", f"P({incident}) [95 %]", "CoV"]
    if onset:
        hd += [f"linear P({ONSET})", f"screening P({ONSET}) ({stat})"]
    rows = []
    for r in runs:
        row = [str(int(r["case"])), *[value_text(a, float(r[f"axis: {a}"]), short=True) for a in axes],
               _g(r["hs"], 4), f"{int(r['samples'])}" + (f" (+{int(r['failed'])} failed)" if r["failed"] else ""),
               f"{_g(r[f'{incident}: P'])} [{_g(r[f'{incident}: P lo'])}, {_g(r[f'{incident}: P hi'])}]",
               _g(r[f"{incident}: CoV"], 2)]
        if onset:
            row += [_g(r["linear first slip: P"]), _g(r[f"screening {stat}"])]
        rows.append(row)
    parts += [f"<h3>Estimates per run (case × Hs level): P({_e(incident)} within the access)</h3>", _table(hd, rows),
              _p("Time domain on the sampled seas, weighted (Au & Beck 2001); 95 % intervals from the estimate's "
                 "coefficient of variation. Every column of every table in isee_runs.md / isee_limits.md names its "
                 "incident.", "note")]
    sections = [("inputs", "Inputs", _inputs_section(data, inputs_from_header(header), extra, seeds=False)),
                ("risk", "Incident and accepted risk", "\n".join(risk)),
                ("decision", "Limiting Hs and estimates", "\n".join(parts)),
                ("sensitivity", "Sensitivity", _sensitivity_section(sensitivity, figures)),
                ("figures", "Figures", _figures_section(figures, incident))]
    return _document(f"{header.get('campaign', 'campaign')}: P({incident})", sections, head)


def write_page(text: str, path: str | Path) -> Path:
    """Write the page ``text`` to ``path`` at once (nothing half-written: :func:`boatland.atomic.atomic_path`)."""
    path = Path(path)
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return path
