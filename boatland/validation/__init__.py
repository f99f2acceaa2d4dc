"""Validation cases a reviewer can rerun: ``boatland validate`` runs them and writes a report.

Each case (:class:`~boatland.validation.case.Case`) names its reference (author, title, year, table or
figure), computes with boatland's own services, measures its error, judges it against its tolerance and
draws a figure; :func:`~boatland.validation.report.write_report` writes the Markdown report. A case that
misses its tolerance is reported as ``MISS`` with its numbers, never left out.

One module per family of cases:

- :mod:`~boatland.validation.hemisphere`: Hulme's hemisphere, three BEM codes, the sphere's IRF;
- :mod:`~boatland.validation.timedomain`: time-domain RAOs against the frequency domain, state space
  against convolution;
- :mod:`~boatland.validation.contact`: the fender contact in closed form;
- :mod:`~boatland.validation.hinge`: the stuck fender's force against the frequency-domain hinge;
- :mod:`~boatland.validation.tank`: Ferreira González's (2023) Model 2 tank runs J01–J04;
- :mod:`~boatland.validation.campaigns`: Grøtting's (2015) trends and the screening against Monte Carlo.

The tests under ``tests/validation/`` call the same functions and keep their own asserts.

Layer: above the services and readers it uses (campaigns, scenario checks, hydro readers), below the CLI.
"""

from __future__ import annotations

from boatland.validation.case import ERROR, MISS, NOT_JUDGED, PASS, Case, CaseResult, Check, Context, Outcome, run_case

__all__ = ["all_cases", "Case", "CaseResult", "Check", "Context", "Outcome", "run_case", "PASS", "MISS", "ERROR",
           "NOT_JUDGED"]


def all_cases() -> list[Case]:
    """Every case, in report order (cheap and analytic first, Monte Carlo last)."""
    from boatland.validation import campaigns, contact, field, hemisphere, hinge, loads, tank, timedomain

    return [*hemisphere.CASES, *timedomain.CASES, *contact.CASES, *hinge.CASES, *tank.CASES, *campaigns.CASES,
            *field.CASES, *loads.CASES]
