"""Everything that refuses or warns before a run, behind one entry point, :func:`check`.

- :mod:`~boatland.checks.physical` — a scenario against its vessel's database (fender on the bow, dt against
  the fender's contact modes, waves in the database's band, hull clear of the pile, directions covered);
- :mod:`~boatland.checks.limits` — values that can only be mistakes (a fender above any deck, a pile wider
  than 20 m, waves past breaking, a push above the vessel's weight);
- :mod:`~boatland.checks.memory` — the radiation memory damps every landed natural mode;
- :mod:`~boatland.checks.files` — a scenario file as a user gives it: load, resolve its database, check,
  report (``boatland scenario check``).

The CLI, the notebook API (:func:`boatland.simulate`) and campaigns all call :func:`check`.
"""

from __future__ import annotations

from boatland.checks.limits import scenario_problems
from boatland.checks.memory import check_memory
from boatland.checks.physical import ScenarioCheck, check_against
from boatland.landing.setup import Setup

__all__ = ["ScenarioCheck", "check"]


def check(scenario, db, *, memory=False, setup: Setup | None = None) -> ScenarioCheck:
    """Every check of ``scenario`` on the vessel of ``db``, problems and warnings with their key paths.

    Parameters
    ----------
    scenario : boatland.scenario.scenario.Scenario
    db : boatland.vessel.database.HydroDB
    memory : bool, RadiationMemory or callable
        Also check the radiation memory at the landed natural modes (:func:`~boatland.checks.memory.check_memory`)
        when the rest holds: ``True`` makes it (:meth:`Setup.memory`); or pass the one the trials will use,
        or a function returning it (called only then).
    setup : Setup, optional
        ``Setup.of(scenario, db)`` when already at hand.

    Returns
    -------
    ScenarioCheck
        ``problems`` (the scenario cannot run), ``warnings``, ``notes`` (what was derived) and the
        ``setup`` it checked (a run starts from it); :meth:`ScenarioCheck.raise_if_problems` raises the
        problems as one :class:`~boatland.tomlspec.SpecError`.
    """
    setup = Setup.of(scenario, db, setup)
    found = check_against(setup)
    problems = found.problems + tuple(p for p in scenario_problems(scenario, db) if p not in found.problems)
    warnings, notes = found.warnings, found.notes + tuple(setup.environment.lines(scenario))
    if memory is not False and not problems and db.M is not None:
        mem = setup.memory() if memory is True else memory() if callable(memory) else memory
        mc = check_memory(setup, mem)
        problems, warnings, notes = problems + mc.problems, warnings + mc.warnings, notes + mc.notes
    return ScenarioCheck(problems=problems, warnings=warnings, notes=notes, setup=setup)
