"""The decision table of a campaign: P(incident within the access) [95 % interval] pivoted by
Hs × Tp × heading, the limiting Hs with its interval, the frequency-domain screening beside each cell,
and how many seeds an interval as narrow as asked would need.

Layout: one *section* per combination of the axes other than Hs, Tp and the wave direction (push,
μ, ...); in it rows are the swept Hs and columns the combinations of Tp and heading. Each cell holds
the Monte Carlo estimate k/n with its Clopper–Pearson interval (:mod:`boatland.campaign.stats`) and any
other estimate the store holds for the case (below). Under each column: the limiting Hs where P reaches
the target, with the interval where the Clopper–Pearson bounds reach it, and "< lowest swept Hs" /
"> highest swept Hs" where it does not cross inside the sweep.

Like with like. The frequency-domain screening (Grøtting 2015 §3.2.1, Wu 2014) predicts slip *onsets*:
its P is that of the incident "first slip" (:data:`ONSET`; its count also holds roll beyond the roll
limit). A cell shows it — "(screening 0.39)" — only in the table of that incident; the table of any
other incident (a slip distance, contact loss, …) shows time-domain figures only and its legend says why
(:meth:`Decision.legend`), so no table sets two incidents side by side without naming each.

Other estimators (hook). A method that estimates P(incident) per case another way — e.g. a rare-event
sampler — stores it in ``/stats`` beside the Monte Carlo columns as ``"<incident>: P (<method>)"``,
``"<incident>: P lo (<method>)"`` and ``"<incident>: P hi (<method>)"`` (float64, NaN where it has none);
:func:`other_estimates` finds them and every table shows them beside the Monte Carlo cell, labelled
``<method>``.

Grøtting, H. (2015), *Small Water Plane Area Solutions for Access of Offshore Wind Turbines*, MSc
thesis, NTNU.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

import numpy as np

from boatland.campaign.labels import (
    DIR_KEYS,
    HS_KEY,
    TP_KEYS,
    axis_label,
    fixed_text,
    inputs_from_header,
    value_text,
)
from boatland.campaign.stats import (
    LimitingHs,
    clopper_pearson,
    limiting_hs_interval,
    seeds_for_width,
)
from boatland.freqdomain.statistics import one_in, probability_text
from boatland.trial.incidents import FirstSlip

__all__ = ["DEFAULT_WIDTH", "ONSET", "SCREENING_NOTE", "Cell", "Decision", "Section", "decision", "other_estimates",
           "p_text"]

#: The incident the frequency-domain screening predicts: the slip onset, "first slip".
ONSET = FirstSlip().name
#: Why the table of another incident shows no screening.
SCREENING_NOTE = f"the frequency-domain screening predicts slip onsets; it is shown beside {ONSET} only"

#: Default width asked of the 95 % interval of P near the target (the seeds advice): ±0.1.
DEFAULT_WIDTH = 0.2

_OTHER = re.compile(r"^(?P<incident>.+): P \((?P<method>[^)]+)\)$")


def other_estimates(stats: np.ndarray, incident: str) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Per-case estimates of P(``incident``) by other methods found in ``stats``: method → (P, lo, hi)
    (see the module docstring for the column names)."""
    out = {}
    for name in stats.dtype.names:
        m = _OTHER.match(name)
        if m and m["incident"] == incident:
            method = m["method"]
            nan = np.full(len(stats), np.nan)
            lo = stats[f"{incident}: P lo ({method})"] if f"{incident}: P lo ({method})" in stats.dtype.names else nan
            hi = stats[f"{incident}: P hi ({method})"] if f"{incident}: P hi ({method})" in stats.dtype.names else nan
            out[method] = (stats[name].astype(float), lo.astype(float), hi.astype(float))
    return out


def p_text(v: float) -> str:
    """A probability in a table: two decimals, below 0.01 three significant figures (``2.69e-3``: a rare
    incident is not "0.00"), below 1e-6 "< 1e-6", "–" when unknown."""
    if v is None or not math.isfinite(v):
        return "–"
    if 0 < v < 1e-6:
        return "< 1e-6"
    return probability_text(v) if 0 < v < 0.01 else f"{v:.2f}"



@dataclass(frozen=True)
class Cell:
    """One case: k incidents in n completed trials, P = k/n with its interval, the screening's
    P(:data:`ONSET` within the access) — whatever incident the table is about — and other methods'
    estimates of the table's incident (method → (P, lo, hi))."""

    case: int
    k: int
    n: int
    p: float
    lo: float
    hi: float
    screening: float
    others: dict = field(default_factory=dict)

    def text(self, *, screening: bool = False) -> str:
        """"0.25 [0.01, 0.81] (screening 0.39)" — the Monte Carlo P with its interval first.

        Parameters
        ----------
        screening : bool
            Show the screening's P beside it: only in the table of :data:`ONSET`, the incident the
            screening predicts (:attr:`Decision.screening_beside`).
        """
        if self.n == 0:
            return "no completed trial"
        out = f"{p_text(self.p)} [{p_text(self.lo)}, {p_text(self.hi)}]"
        extra = []
        if screening and math.isfinite(self.screening):
            extra.append(f"screening {p_text(self.screening)}")
        for method, (p, lo, hi) in self.others.items():
            if math.isfinite(p):
                extra.append(f"{method} {p_text(p)}" + (f" [{p_text(lo)}, {p_text(hi)}]" if math.isfinite(lo) else ""))
        return out + (f" ({'; '.join(extra)})" if extra else "")

    def as_dict(self) -> dict:
        """JSON-able; the screening's figure keyed by the incident it is of (``screening_P_first_slip``)."""
        nan = lambda v: None if v is None or not math.isfinite(v) else float(v)
        return {"case": self.case, "incidents": self.k, "trials": self.n, "P": nan(self.p), "P_lo": nan(self.lo),
                "P_hi": nan(self.hi), "screening_P_first_slip": nan(self.screening),
                "other_estimates": {m: {"P": nan(p), "P_lo": nan(lo), "P_hi": nan(hi)}
                                    for m, (p, lo, hi) in self.others.items()}}


@dataclass(frozen=True)
class Section:
    """One combination of the axes other than Hs, Tp and direction: ``fixed`` (key → value), the Hs
    rows, the (Tp, direction) columns, the cells ``cells[(row, column)]`` and the limiting Hs per column."""

    fixed: dict
    rows: list
    columns: list
    column_keys: tuple
    cells: dict
    limits: dict

    def title(self) -> str:
        return ", ".join(value_text(k, v) for k, v in self.fixed.items()) or "all cases"

    def column_text(self, col) -> str:
        return ", ".join(value_text(k, v) for k, v in zip(self.column_keys, col)) or "all"


@dataclass(frozen=True)
class Decision:
    """The decision table of a campaign store (:func:`decision`)."""

    campaign: str
    incident: str
    target: float
    confidence: float
    width: float
    seeds: int
    axes: list
    inputs: dict
    sections: list
    seeds_needed: int | None
    widest: float

    @property
    def column_keys(self) -> tuple:
        return self.sections[0].column_keys if self.sections else ()

    @property
    def screening_beside(self) -> bool:
        """Whether the cells show the screening's P: only when the table's incident is :data:`ONSET`."""
        return self.incident == ONSET

    def legend(self) -> str:
        """What a cell holds, in words, naming the incident of every figure in it."""
        cell = (f"each cell: Monte Carlo P({self.incident} within the access) [Clopper–Pearson "
                f"{100 * self.confidence:g} %]")
        if self.screening_beside:
            return cell + f" (screening: the frequency-domain screening's P({ONSET} within the access))"
        return cell + f"; time domain only — {SCREENING_NOTE}"

    def heading(self) -> str:
        fixed = fixed_text(self.inputs, self.axes)
        return (f"{self.campaign}: P({self.incident} within the access) [{100 * self.confidence:g} % interval]"
                + (f" — {fixed}" if fixed else ""))

    def axes_text(self) -> str:
        cols = " × ".join(axis_label(k) for k in self.column_keys) or "–"
        return f"rows {axis_label(HS_KEY) if HS_KEY in self.axes else 'all cases'}; columns {cols}"

    def advice(self) -> str:
        """How many seeds per case an interval of the asked width needs near the target."""
        have = f"{self.seeds} seed{'s' if self.seeds != 1 else ''} per case: the {100 * self.confidence:g} % " \
               f"intervals of P are up to {p_text(self.widest)} wide"
        if self.seeds_needed is None:
            return have + f"; an interval of {self.width:g} at P ≈ {self.target:g} needs more than 100000 seeds"
        if self.seeds_needed <= self.seeds:
            return have + f"; enough for intervals of {self.width:g} at P ≈ {self.target:g} (--width)"
        return have + (f"; for intervals of {self.width:g} at P ≈ {self.target:g} (--width {self.width:g}) run about "
                       f"{self.seeds_needed} seeds per case")

    def as_dict(self) -> dict:
        sections = []
        for s in self.sections:
            sections.append({
                "fixed": s.fixed, "title": s.title(), "rows": {"key": HS_KEY, "values": s.rows},
                "columns": [{"values": dict(zip(s.column_keys, c)), "label": s.column_text(c)} for c in s.columns],
                "cells": [[s.cells[(r, c)].as_dict() if (r, c) in s.cells else None for c in s.columns] for r in s.rows],
                "limiting_hs": [{"column": s.column_text(c), **s.limits[c].as_dict()} if c in s.limits else None
                                for c in s.columns],
            })
        return {"campaign": self.campaign, "incident": self.incident, "target": self.target,
                "confidence": self.confidence, "seeds_per_case": self.seeds, "axes": self.axes, "inputs": self.inputs,
                "widest_interval": self.widest, "width": self.width, "seeds_needed": self.seeds_needed,
                "advice": self.advice(), "sections": sections}

    # ------------------------------------------------------------------ rendering
    def table_lines(self, section: Section, *, markdown: bool) -> list[str]:
        head = [axis_label(HS_KEY) if HS_KEY in self.axes else "case"] + [section.column_text(c) for c in section.columns]
        body = []
        for r in section.rows:
            first = f"{r:g}" if isinstance(r, float) else str(r)
            body.append([first] + [section.cells[(r, c)].text(screening=self.screening_beside)
                                   if (r, c) in section.cells else "–"
                                   for c in section.columns])
        if section.limits:
            body.append([f"limiting Hs at P = {self.target:g} ({one_in(self.target)})"]
                        + [section.limits[c].text() if c in section.limits else "–" for c in section.columns])
        if markdown:
            return ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)] + ["| " + " | ".join(b) + " |" for b in body]
        widths = [max(len(row[i]) for row in [head] + body) for i in range(len(head))]
        fmt = lambda row: "  ".join(v.ljust(w) for v, w in zip(row, widths)).rstrip()
        return [fmt(head)] + [fmt(b) for b in body]

    def markdown(self) -> str:
        lines = [f"# {self.heading()}", "", f"{self.axes_text()}; {self.legend()}", ""]
        for s in self.sections:
            if len(self.sections) > 1:
                lines += [f"## {s.title()}", ""]
            lines += self.table_lines(s, markdown=True) + [""]
        lines += [(f"Limiting Hs: where P reaches {self.target:g}, linear between the swept Hs; its interval is where "
                   f"the Clopper–Pearson bounds of P reach it; \"<\" / \">\": it does not cross inside the sweep."), "",
                  self.advice() + "."]
        return "\n".join(lines) + "\n"

    def text(self) -> str:
        cells = f"cells: P({self.incident}) [interval]" + (f" (screening P({ONSET}))" if self.screening_beside
                                                             else f"; {SCREENING_NOTE}")
        lines = [self.heading(), f"  {self.axes_text()}; {cells}"]
        for s in self.sections:
            if len(self.sections) > 1:
                lines.append(f"  {s.title()}:")
            lines += ["    " + ln for ln in self.table_lines(s, markdown=False)]
        lines.append("  " + self.advice())
        return "\n".join(lines)


def _value(stats, key, i):
    v = stats[f"axis: {key}"][i]
    return float(v)


def decision(data: dict, incident: str, target: float = 0.1, *, width: float = DEFAULT_WIDTH,
             confidence: float = 0.95) -> Decision:
    """The decision table of a store read by :func:`boatland.campaign.report.read_store`.

    Parameters
    ----------
    incident : str
        One of the store's incident definitions.
    target : float
        Accepted probability of the incident within the access (for the limiting Hs).
    width : float
        Width asked of the interval of P near the target (the seeds advice).
    """
    stats, plan, header = data["stats"], data["plan"], data["header"]
    axes = list(plan["axes"])
    col_keys = tuple(k for k in (*TP_KEYS, *DIR_KEYS) if k in axes)
    other_keys = [k for k in axes if k != HS_KEY and k not in col_keys]
    others = other_estimates(stats, incident)
    by_section: dict[tuple, list[int]] = {}
    for i in range(len(stats)):
        by_section.setdefault(tuple(_value(stats, k, i) for k in other_keys), []).append(i)
    sections = []
    for fixed_vals, idx in by_section.items():
        cells, rows, columns = {}, [], []
        for i in idx:
            r = _value(stats, HS_KEY, i) if HS_KEY in axes else int(stats["case"][i])
            c = tuple(_value(stats, k, i) for k in col_keys)
            n = int(stats["trials"][i]) - int(stats["failed"][i])
            k = int(stats[f"{incident}: count"][i])
            p, lo, hi = clopper_pearson(k, n, confidence)
            cells[(r, c)] = Cell(int(stats["case"][i]), k, n, p, lo, hi, float(stats["screening: P(slip)"][i]),
                                 {m: (float(a[i]), float(b[i]), float(h[i])) for m, (a, b, h) in others.items()})
            rows.append(r)
            columns.append(c)
        rows = sorted(set(rows))
        columns = sorted(set(columns), key=lambda c: tuple(-v if j == len(c) - 1 and col_keys[-1] in DIR_KEYS else v
                                                            for j, v in enumerate(c)))
        limits: dict[tuple, LimitingHs] = {}
        if HS_KEY in axes and len(rows) >= 1:
            for c in columns:
                got = [(r, cells[(r, c)]) for r in rows if (r, c) in cells and cells[(r, c)].n > 0]
                if got:
                    hs = [r for r, _ in got]
                    limits[c] = limiting_hs_interval(hs, [x.p for _, x in got], [x.lo for _, x in got],
                                                     [x.hi for _, x in got], target)
        sections.append(Section(dict(zip(other_keys, fixed_vals)), rows, columns, col_keys, cells, limits))
    seeds = int(plan.get("seeds", 0)) or int(max(stats["trials"]))
    widths = [c.hi - c.lo for s in sections for c in s.cells.values() if c.n > 0]
    return Decision(campaign=str(header.get("campaign", plan.get("name", ""))), incident=incident, target=target,
                    confidence=confidence, width=width, seeds=seeds, axes=axes, inputs=inputs_from_header(header),
                    sections=sections, seeds_needed=seeds_for_width(target, width, confidence),
                    widest=max(widths) if widths else float("nan"))
