"""The notebook API: load a scenario, change any key, run a trial, get labelled data back.

>>> import boatland
>>> r = boatland.simulate("ctv_landing", **{"sea.Hs": 1.0, "simulation.duration": 120})   # doctest: +SKIP
>>> r.verdict().text()                                                                     # doctest: +SKIP
>>> ds = r.to_xarray()                         # time × dof / contact, units, inputs     # doctest: +SKIP

Changes are key paths as in a scenario file (``"sea.Hs"``, ``"fender.mu_s"``,
``"landing.struts[1].diameter"``; ``None`` removes a key), given as keyword arguments — with dots via
``**{"sea.Hs": 1.0}``, or with double underscores, ``sea__Hs=1.0`` — and/or as a ``changes`` dict.
Every change is validated as the file is (all problems at once, with their key paths).
"""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any, Mapping

from boatland.campaign.job import campaign, campaign_path
from boatland.tomlspec import key_changes

__all__ = ["load_scenario", "simulate", "scenario_path", "campaign", "campaign_path"]


def scenario_path(name: str | Path | None = None) -> Path:
    """A scenario file: a path, or the name of one shipped in ``scenarios/`` (``"ctv_landing"``,
    ``"model2_j03"``); None: the default trial (``scenarios/ctv_landing.toml``)."""
    from boatland.errors import BoatlandInputError
    from boatland.checks.files import default_scenario_path
    from boatland.resources import path_or_shipped, shipped_names

    if name is None:
        return default_scenario_path()
    found = path_or_shipped(name)
    if found is not None:
        return found
    raise BoatlandInputError(f"{name}: no such file, and not a shipped scenario ({', '.join(shipped_names())})")


def load_scenario(scenario=None, *, changes: Mapping[str, Any] | None = None, **overrides):
    """A validated :class:`~boatland.scenario.scenario.Scenario`, with changes.

    Parameters
    ----------
    scenario : path, str, Scenario or None
        A scenario file, the name of a shipped one (:func:`scenario_path`), a Scenario (changed and
        returned), or None for the default trial.
    changes : mapping, optional
        Key path → value (``{"sea.Hs": 1.0, "thrust.force": 60e3}``).
    **overrides
        More changes: ``**{"sea.Hs": 1.0}`` or ``sea__Hs=1.0``.

    Raises
    ------
    boatland.tomlspec.SpecError
        Every problem of the file and the changes, with its key path.
    """
    from boatland.scenario.scenario import Scenario
    from boatland.checks.files import load

    sc = scenario if isinstance(scenario, Scenario) else load(scenario_path(scenario))
    todo = key_changes(changes, overrides)
    return sc.replace(todo) if todo else sc


def simulate(scenario=None, *, changes: Mapping[str, Any] | None = None, log: str | Path | None = None,
             progress=None, **overrides):
    """Run one landing trial, as ``boatland run`` does, and return its
    :class:`~boatland.trial.result.Result` (``.verdict()``, ``.summary()``, ``.to_xarray()``).

    Parameters
    ----------
    scenario : path, str, Scenario or None
        As :func:`load_scenario` (None: the default trial, ``scenarios/ctv_landing.toml``).
    changes : mapping, optional
        Key path → value.
    log : path, optional
        Also write the run log (MCAP) there, as ``boatland run --log`` does.
    progress : callable, optional
        ``progress(steps_done, n_steps)`` while the kernel runs.
    **overrides
        More changes: ``**{"sea.Hs": 1.0}`` or ``sea__Hs=1.0``.

    Returns
    -------
    Result

    Raises
    ------
    boatland.tomlspec.SpecError
        Problems of the scenario, its changes or its database (all at once, with key paths).
    boatland.trial.simulate.BlowUpError
        The integration stopped (NaN or runaway); its ``result`` holds the trial up to there.

    Notes
    -----
    The scenario's checks against its database run first, as in ``boatland run``; their warnings are
    issued as :class:`boatland.scenario.scenario.ScenarioWarning`.
    """
    from boatland.checks.files import check_loaded
    from boatland.trial.simulate import simulate as run

    sc = load_scenario(scenario, changes=changes, **overrides)
    db, found = check_loaded(sc)
    sinks = []
    if log is not None:
        from boatland.record.mcap_log import McapLog

        sinks.append(McapLog(Path(log)))
    try:
        with warnings.catch_warnings():   # numba compiling the sinks' gate (object mode by design): not for users
            warnings.filterwarnings("ignore", message="Code running in object mode won't allow parallel execution")
            return run(sc, db, sinks=sinks, progress=progress, setup=found.setup)
    finally:
        for s in sinks:
            s.close()

