"""What a validation case is, what it returns, and how a list of them is run.

A :class:`Case` names its reference (who, where: author, title, year, table or figure), says what is
computed, how the error is measured and what the tolerance is; its ``run`` function computes, draws its
figure and returns an :class:`Outcome` — a list of :class:`Check` rows, each judged against its own
tolerance (or explicitly not judged, when the reference states nothing to judge against).

Verdicts: ``PASS`` every judged check within its tolerance; ``MISS`` at least one outside it (the case
stays in the report with its numbers — a miss is a result, never dropped); ``ERROR`` the computation
itself failed (the message is reported in the case's place).
"""

from __future__ import annotations

import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

__all__ = ["Case", "Check", "Outcome", "Context", "CaseResult", "run_case", "PASS", "MISS", "ERROR",
           "NOT_JUDGED"]

PASS, MISS, ERROR = "PASS", "MISS", "ERROR"
#: A check the reference gives no statement to judge against: its figures are reported, not judged.
NOT_JUDGED = "not judged"


@dataclass(frozen=True)
class Check:
    """One comparison of a case.

    Attributes
    ----------
    what : str
        What is compared (e.g. ``"μ = A33/(ρV), 0.05 ≤ kA ≤ 8"``).
    measured : str
        The error (or outcome) measured, formatted for the report.
    tolerance : str
        What it is judged against, formatted for the report.
    passed : bool or None
        Within the tolerance; None when the reference states nothing to judge against (reported only).
    error : float or None
        The error as a number, where it is one (the JSON output carries it).
    limit : float or None
        The tolerance as a number, where it is one.
    """

    what: str
    measured: str
    tolerance: str
    passed: bool | None
    error: float | None = None
    limit: float | None = None

    @property
    def verdict(self) -> str:
        return NOT_JUDGED if self.passed is None else (PASS if self.passed else MISS)

    @classmethod
    def below(cls, what: str, error: float, limit: float, fmt: str = "{:.3g}", unit: str = "") -> "Check":
        """A check ``error < limit`` of one number, both printed with ``fmt`` and ``unit``."""
        return cls(what, fmt.format(error) + unit, "< " + fmt.format(limit) + unit, bool(error < limit),
                   float(error), float(limit))

    @classmethod
    def percent(cls, what: str, error: float, limit: float, digits: int = 2) -> "Check":
        """A relative error ``error < limit`` (fractions), printed in per cent."""
        f = f"{{:.{digits}f}}"
        return cls(what, f.format(100 * error) + " %", "< " + f"{100 * limit:g}" + " %", bool(error < limit),
                   float(error), float(limit))


@dataclass
class Outcome:
    """What a case's computation returns.

    Attributes
    ----------
    checks : list of Check
    headline : str
        The error in one short phrase for the summary table (e.g. ``"max 0.28 %"``).
    figure : str or None
        File name of the case's figure in the report folder.
    notes : list of str
        Paragraphs for the report (what was seen, what the numbers mean, settings used).
    settings : str
        The settings that were run (seeds, durations; what ``--quick`` reduced).
    """

    checks: list[Check]
    headline: str
    figure: str | None = None
    notes: list[str] = field(default_factory=list)
    settings: str = ""


@dataclass(frozen=True)
class Context:
    """What a case's computation may use.

    Attributes
    ----------
    quick : bool
        Cheaper settings (fewer seeds, shorter records, fewer periods): ``boatland validate --quick``.
    refdata : Path or None
        The public reference data folder (a checkout's ``tests/data/refdata``).
    scenarios : Path
        The checkout's ``scenarios/`` folder (the default scenario and the tank runs).
    out : Path
        The report folder (figures are written there).
    work : Path
        A scratch folder for campaign stores (removed afterwards).
    workers : int
        Local worker processes for the campaign cases.
    progress : callable
        Prints one line of progress.
    """

    quick: bool
    refdata: Path | None
    scenarios: Path
    out: Path
    work: Path
    workers: int = 2
    progress: Callable[[str], None] = print

    def save(self, fig, name: str) -> str:
        """Write a matplotlib figure as ``out/name`` (PNG, temp file + rename) and close it; returns ``name``."""
        import matplotlib.pyplot as plt

        from boatland.atomic import atomic_path

        with atomic_path(self.out / name) as tmp:
            fig.savefig(tmp, format="png", dpi=90)
        plt.close(fig)
        return name


@dataclass(frozen=True)
class Case:
    """One validation case.

    Attributes
    ----------
    name : str
        Short identifier (``boatland validate --case NAME``).
    title : str
        Heading in the report.
    reference : str
        Who and where: author, title, year, and the table, figure or section compared with.
    computation : str
        What boatland computes (Markdown, one paragraph).
    error_measure : str
        How the difference is measured.
    tolerance : str
        The tolerance, short (the summary table's column).
    run : callable
        ``run(ctx: Context) -> Outcome``.
    quick : str
        What ``--quick`` changes ("" = nothing: the full case is cheap).
    refdata_files : tuple of str
        Files of the reference data folder it reads (checked before anything runs).
    scenario_files : tuple of str
        Files of the checkout's ``scenarios/`` folder it reads.
    cite : str
        The reference in a few words (the summary table's column).
    """

    name: str
    title: str
    reference: str
    computation: str
    error_measure: str
    tolerance: str
    run: Callable[[Context], Outcome]
    quick: str = ""
    refdata_files: tuple[str, ...] = ()
    scenario_files: tuple[str, ...] = ()
    cite: str = ""


@dataclass
class CaseResult:
    """A case as run: its outcome (or the error that stopped it), verdict and wall time."""

    case: Case
    outcome: Outcome | None
    verdict: str
    seconds: float
    error: str = ""

    def to_dict(self) -> dict:
        c, o = self.case, self.outcome
        return {
            "name": c.name, "title": c.title, "cite": c.cite, "reference": c.reference, "tolerance": c.tolerance,
            "error_measure": c.error_measure, "verdict": self.verdict, "wall_time_s": round(self.seconds, 1),
            "headline": o.headline if o else self.error, "figure": o.figure if o else None,
            "settings": o.settings if o else "", "error": self.error,
            "checks": [{"what": k.what, "measured": k.measured, "tolerance": k.tolerance, "verdict": k.verdict,
                        "error": k.error, "limit": k.limit} for k in (o.checks if o else [])],
        }


def run_case(case: Case, ctx: Context) -> CaseResult:
    """Run one case; an exception becomes an ``ERROR`` result (its traceback printed through
    ``ctx.progress``), never the end of the batch."""
    t0 = time.perf_counter()
    try:
        outcome = case.run(ctx)
    except Exception as exc:  # noqa: BLE001 — recorded as the case's result; the other cases still run
        seconds = time.perf_counter() - t0
        ctx.progress("".join(traceback.format_exception(exc)).rstrip())
        return CaseResult(case, None, ERROR, seconds, f"{type(exc).__name__}: {exc}".splitlines()[0][:300])
    seconds = time.perf_counter() - t0
    judged = [k for k in outcome.checks if k.passed is not None]
    verdict = PASS if judged and all(k.passed for k in judged) else MISS
    if not judged:
        verdict = ERROR
        return CaseResult(case, outcome, verdict, seconds, "no check could be judged")
    return CaseResult(case, outcome, verdict, seconds)
