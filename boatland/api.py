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

__all__ = ["load_scenario", "simulate", "scenario_path", "campaign", "campaign_path", "operability"]


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



def operability(scenario, weather, *, landings=None, window: float | None = 4.0, accept="best",
                changes: Mapping[str, Any] | None = None, **overrides):
    """A vessel's access at a turbine's landings over a site's weather, as ``boatland operability`` judges it
    (:mod:`boatland.site`): availability per landing and with the best landing, per month and year, windows.

    Parameters
    ----------
    scenario : path, str or Scenario
        As :func:`load_scenario` (judged by the frequency-domain screening) — or the path of a rare-event
        campaign's store (``.h5``), judged by its time-domain limits (:class:`boatland.site.LimitsTable`).
    weather : path or boatland.site.Weather
        A scatter diagram or hindcast file (:func:`boatland.site.read_weather`), or one read.
    landings : sequence of float, optional
        Compass bearings of the landings from the tower's axis [deg]; default the scenario's own landing (its
        vessel heading + 180°; a store needs them given).
    window : float or None
        Access window of a hindcast [h] (4 h: an assumption, a short visit).
    accept : float or str
        Accepted probability of an incident per 30-min access (the screening's; a store has its own).
    changes, **overrides
        Changes of the scenario, as :func:`load_scenario`.

    Returns
    -------
    boatland.site.Operability
        ``.availability()``, ``.monthly()``, ``.windows``, ``.text()``, ``.as_dict()``.
    """
    from boatland.checks.files import check_loaded
    from boatland.errors import BoatlandInputError
    from boatland.freqdomain import LandingSetup
    from boatland.site import LimitsTable, Weather, flow_setups, landing_bearing, read_weather, table_operability
    from boatland.site import operability as judge

    w = weather if isinstance(weather, Weather) else read_weather(weather)
    if isinstance(scenario, (str, Path)) and Path(scenario).suffix.lower() in (".h5", ".hdf5"):
        if landings is None:
            raise BoatlandInputError("landings: give the landings' compass bearings (a limits store does not say "
                                     "where its landing is on the tower)")
        return table_operability(LimitsTable.read(scenario), w, landings, window_hours=window)
    sc = load_scenario(scenario, changes=changes, **overrides)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        db, _ = check_loaded(sc)
    parts = getattr(getattr(sc.sea, "waves", None), "parts", None)
    L = [float(landing_bearing(sc.vessel.heading_deg))] if landings is None else landings
    extra = {} if w.current is None and w.wind is None else {"flow_setup": flow_setups(sc, db)}
    return judge(db, LandingSetup.from_scenario(sc, db), w, L, name=sc.name, window_hours=window, accept=accept,
                 sea=parts[0] if parts else None, water_depth=sc.sea.water_depth if sc.sea is not None else None,
                 **extra)
