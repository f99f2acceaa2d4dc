"""A campaign's work done once, before and beside its trials: the checks of every case, each case's shared
data, the pile's tables and the frequency-domain screening.

Work done once per campaign, not per trial or worker: :func:`check_cases` runs every case through the
checks ``boatland run`` makes (:func:`boatland.checks.check`) and makes each radiation memory (IRFs and
state-space fit) once; :func:`prepare_cases` compiles the kernel arrays of each case from it; the ω
tables of the pile's scattered wave the trials interpolate are made once for the whole campaign, every
wave direction of a layout in one pass (:func:`campaign_tables`, :func:`boatland.sea.pile.make_tables`).
Every trial is shipped its case's :class:`CaseData`, so no worker makes either again. They are the values
a worker would have made (the same functions, pinned to one BLAS thread): the store is the same bit for
bit. With several workers the tables and then the frequency-domain screening are made in a process of
its own (:class:`BackgroundWork`), which starts before the checks, on the core they leave idle.

A worker keeps the campaign and what it made between its tasks (:func:`worker_context`).
"""

from __future__ import annotations

import math
import os
import warnings
from dataclasses import dataclass

import numpy as np

from boatland.campaign.executor import kill_pool, process_pool
from boatland.campaign.plan import Campaign, TrialSpec, trial_seed
from boatland.reproducible import single_threaded
from boatland.sea.spectra import SHAPES
from boatland.trial.motion import MotionArrays
from boatland.trial.simulate import exposure_start

__all__ = ["BackgroundWork", "CaseData", "CasePreparation", "campaign_tables", "check_cases", "database_for",
           "first_trial",
           "case_screening", "case_sensitivity", "checked_inputs", "memory_key", "prepare_cases", "start_background", "worker_context"]


#: Per worker process: the campaign, its databases and radiation memories (:func:`worker_context`).
_WORKER: dict = {}


#: Per campaign process: what :func:`check_cases` made, by (campaign digest, database loader).
_CHECKED: dict = {}


@dataclass(frozen=True, eq=False)
class CaseData:
    """What every trial of one case shares, made once per campaign (:func:`prepare_cases`) and shipped with
    the trials to whichever worker runs them.

    Attributes
    ----------
    arrays : MotionArrays
        The kernel arrays compiled from the case's radiation memory, which :func:`check_cases` checked
        at the case's landed modes (:func:`boatland.trial.simulate.motion_arrays`).
    tables : tuple of ScatteredTable
        The ω tables of the pile's scattered wave its trials interpolate
        (:func:`boatland.trial.simulate.pile_tables`; empty without a pile or for short-crested seas).
    """

    arrays: MotionArrays
    tables: tuple = ()


def worker_context(campaign: Campaign, loaders) -> dict:
    """What a worker process keeps between the tasks of one campaign: the campaign it was sent (never read
    again from its files) and the databases, radiation memories, kernel arrays and checked cases it has
    made (``{"campaign", "db", "memory", "arrays", "checked"}``; one campaign at a time, by
    :attr:`~boatland.campaign.plan.Campaign.identity`)."""
    key = (campaign.identity, loaders)
    if key not in _WORKER:
        _WORKER.clear()
        _WORKER[key] = {"campaign": campaign, "db": {}, "memory": {}, "arrays": {}, "checked": set()}
    return _WORKER[key]


def database_for(scenario, databases: dict, load_database):
    """The database of ``scenario``, loaded once per key into ``databases`` (a process's or a campaign's
    cache by :attr:`~boatland.scenario.parts.VesselSetup.database_key`)."""
    key = scenario.vessel.database_key
    if key not in databases:
        databases[key] = load_database(scenario)
    return databases[key]


def memory_key(dbkey: str, rad) -> tuple:
    """The radiation memory a scenario needs: its database and radiation settings."""
    return (dbkey, rad.method, rad.memory, rad.tail, rad.taper)


def first_trial(campaign: Campaign, case: int) -> TrialSpec:
    """The first trial of ``case`` (its scenario is the case's)."""
    return TrialSpec(case * campaign.seeds, case, 0, trial_seed(campaign.master_seed, 0))


def check_cases(campaign: Campaign, load_database) -> list[str]:
    """The checks ``boatland run`` makes, for every case's scenario, before any trial
    (:func:`boatland.checks.check`): the scenario against its database (dt against the fender contact,
    the fender on the bow, ...), the limits of :mod:`boatland.checks.limits` and the radiation memory at
    the landed modes (:func:`boatland.checks.memory.check_memory`).

    Returns the warnings (one line each, naming the case); raises :class:`SpecError` with every problem
    of every case (key paths prefixed by the case).

    The radiation memories it makes are the ones the trials use (:func:`prepare_cases`); they and the
    outcome are kept in this process for the same campaign (its :meth:`~Campaign.digest`: files and their
    contents) and loader, so checking again (``run_campaign`` after the CLI) costs nothing.
    """
    return list(_checked(campaign, load_database)["warnings"])


def checked_inputs(campaign: Campaign, load_database) -> tuple[str, dict, dict]:
    """``(digest, input digests, databases)`` of the inputs :func:`check_cases` read: the campaign's
    :meth:`~Campaign.digest` and :meth:`~Campaign.input_digests` as they were while its databases were
    loaded (checked unchanged from before to after the loading), and those databases by key — what the
    trials run on and what a store records."""
    checked = _checked(campaign, load_database)
    return checked["digest"], checked["inputs"], checked["dbs"]


def _checked(campaign: Campaign, load_database) -> dict:
    """:func:`check_cases`'s work, kept: ``{"warnings", "dbs", "memories", "setups", "digest", "inputs"}``
    (each case's :class:`~boatland.landing.setup.Setup`, by case index).

    Raises
    ------
    BoatlandInputError
        An input file changed while the databases were being read (named; nothing has run).
    """
    before = campaign.input_digests()
    key = (campaign.digest(before), load_database)
    if key in _CHECKED:
        return _CHECKED[key]
    from boatland.checks import check
    from boatland.landing.setup import Setup
    from boatland.tomlspec import SpecError

    problems, warns, dbs, setups = [], [], {}, {}
    memories: dict = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for case in campaign.cases:
            sc = campaign.scenario_for(first_trial(campaign, case.index))
            db = database_for(sc, dbs, load_database)
            setup = setups[case.index] = Setup.of(sc, db)
            mkey = memory_key(sc.vessel.database_key, sc.radiation)

            def memory(setup=setup, mkey=mkey):    # made when the rest of the case holds, once per memory
                if mkey not in memories:
                    memories[mkey] = setup.memory()   # pinned to one BLAS thread, as in a trial
                return memories[mkey]

            found = check(sc, db, memory=memory, setup=setup)
            where = f"case {case.index} ({case.label() or 'base'})"
            problems += [(f"{where}: {k}", m) for k, m in found.problems]
            warns += [(case.index, where, f"{k}: {m}") for k, m in found.warnings]
    if problems:
        raise SpecError(campaign.source, problems)
    after = campaign.input_digests()               # what was loaded is what was hashed, or nothing runs
    changed = [name for name in before if before[name] != after.get(name)]
    if changed:
        from boatland.errors import BoatlandInputError

        raise BoatlandInputError(f"{changed[0]}: changed while the campaign was reading its inputs; nothing has "
                                 "run — run the same command again")
    _CHECKED.clear()                               # one campaign at a time: bounded memory
    _CHECKED[key] = {"warnings": _grouped(warns, len(campaign.cases)), "dbs": dbs, "memories": memories,
                     "setups": setups, "digest": key[0], "inputs": before}
    return _CHECKED[key]


def _grouped(warns, n_cases: int) -> tuple[str, ...]:
    """One line per warning text: the case that gave it, or the cases that gave the same ("cases 0–23 (all
    24): …") — a campaign's cases often share their vessel's warnings."""
    by_text: dict[str, list] = {}
    for index, where, text in warns:
        by_text.setdefault(text, []).append((index, where))
    lines = []
    for text, cases in by_text.items():
        cases = sorted(dict.fromkeys(cases))
        if len(cases) == 1:
            lines.append(f"{cases[0][1]}: {text}")
            continue
        idx = [i for i, _ in cases]
        span = f"{idx[0]}–{idx[-1]}" if idx == list(range(idx[0], idx[-1] + 1)) else ", ".join(map(str, idx))
        every = f" (all {n_cases})" if len(idx) == n_cases else f" ({len(idx)} of {n_cases})"
        lines.append(f"cases {span}{every}: {text}")
    return tuple(lines)


def prepare_cases(campaign: Campaign, load_database, cases=None) -> dict[int, CaseData]:
    """Each case's :class:`CaseData`, made once in this process: the kernel arrays from the radiation
    memory :func:`check_cases` made and checked (it runs first if it has not), and the ω tables of the
    pile's scattered wave (≈ 0.5–1 s each for the ctv24 mesh; one per layout and wave direction, shared by
    the cases that have the same). Pinned to one BLAS thread, as a trial: the values a worker would make.

    Parameters
    ----------
    campaign : Campaign
    load_database : callable
        ``load_database(scenario) -> HydroDB`` (the edge's loader).
    cases : iterable of int, optional
        The cases to prepare (default: all).

    Returns
    -------
    dict
        case → CaseData; a case whose preparation fails (a state-space pole too fast for its dt, the
        hull inside the pile, ...) is left out: its trials then make everything themselves and record
        the same error as before.
    """
    prepared = CasePreparation(campaign, load_database)
    return {case: data for case in (range(len(campaign.cases)) if cases is None else cases)
            if (data := prepared.get(case)) is not None}


class CasePreparation:
    """case → :class:`CaseData` (or None), made the first time it is asked for — when the first trial of the
    case is handed to the executor, so that the workers start on the first case while the next ones are
    prepared. Kernel arrays are compiled once per radiation memory and time step; the pile's tables of
    every case are made together when the first case is (:func:`campaign_tables`), or taken from
    ``background`` (:class:`BackgroundWork`) which made them beside the checks."""

    def __init__(self, campaign: Campaign, load_database, background: "BackgroundWork | None" = None):
        self.campaign, self.checked = campaign, _checked(campaign, load_database)
        self.load_database, self.background = load_database, background
        self.cases: dict = {}
        self.arrays: dict = {}
        self.tables_in = False

    def get(self, case: int) -> CaseData | None:
        if case not in self.cases:
            with warnings.catch_warnings(), single_threaded():
                warnings.simplefilter("ignore")
                if not self.tables_in:
                    from boatland.sea.pile import remember_tables

                    self.tables_in = True
                    remember_tables(self.background.tables() if self.background is not None else
                                    campaign_tables(self.campaign, self.load_database, self.checked["dbs"],
                                                    self.checked["setups"]))
                try:
                    self.cases[case] = self._prepare(case)
                except Exception:  # noqa: BLE001 — its trials meet it again and record it
                    self.cases[case] = None
        return self.cases[case]

    def _prepare(self, case: int) -> CaseData:
        from boatland.trial.simulate import motion_arrays, pile_tables

        setup = self.checked["setups"][case]               # the one the checks looked at
        sc = setup.scenario
        dbkey = sc.vessel.database_key
        mkey = memory_key(dbkey, sc.radiation)
        akey = (mkey, setup.dt)
        if akey not in self.arrays:
            self.arrays[akey] = motion_arrays(setup, self.checked["memories"][mkey])
        return CaseData(arrays=self.arrays[akey], tables=tuple(pile_tables(setup)))


def campaign_tables(campaign: Campaign, load_database, dbs: dict | None = None, setups: dict | None = None) -> list:
    """The ω tables of the pile's scattered wave of every case (:func:`boatland.trial.simulate.pile_tables`),
    the directions of each database and layout made together
    (:func:`boatland.sea.pile.make_tables`; three directions of the ctv24: 1.4 s instead of
    2.6 s). None at all when there are more than a process keeps (then each case makes its own), and none
    for a case whose tables fail: its own preparation meets the error again. ``dbs``, ``setups``: the
    databases (by key) and the cases' setups (by case) the checks made, where at hand."""
    from boatland.landing.setup import Setup
    from boatland.sea.pile import TABLE_CACHE_SIZE, make_tables
    from boatland.trial.simulate import pile_table_request

    requests: dict = {}
    dbs = {} if dbs is None else dict(dbs)      # databases by key, loaded where missing
    for case in campaign.cases:
        try:
            setup = (setups or {}).get(case.index)
            sc = setup.scenario if setup is not None else campaign.scenario_for(first_trial(campaign, case.index))
            dbkey = sc.vessel.database_key
            if setup is None:
                setup = Setup.of(sc, database_for(sc, dbs, load_database))
            request = pile_table_request(setup)
        except Exception:  # noqa: BLE001
            continue
        if request is not None:
            requests.setdefault(dbkey, []).append(request)
    if sum(np.unique(r.theta).size for rs in requests.values() for r in rs) > TABLE_CACHE_SIZE:
        return []
    tables = []
    for dbkey, rs in requests.items():
        try:
            tables += make_tables(dbs[dbkey], rs)
        except Exception:  # noqa: BLE001 — e.g. the hull inside the pile: the cases say so themselves
            continue
    return tables


def start_background(campaign: Campaign, loaders, executor: str = "local",
                     workers: int | None = None) -> "BackgroundWork | None":
    """The campaign's work beside the trials (:class:`BackgroundWork`: the pile's tables, then the
    frequency-domain screening) started in a process of its own — or None when the trials run in this
    process (one local worker: the tables are then made with the first case, the screening after the
    trials, here). Pass it to :func:`run_campaign`; :meth:`BackgroundWork.close` it if the campaign does
    not run."""
    if executor == "local" and (workers or os.cpu_count() or 1) == 1:
        return None
    return BackgroundWork(campaign, loaders)


def case_screening(campaign: Campaign, loaders) -> tuple[np.ndarray, list[str]]:
    """The frequency-domain screening's P(slip within the access) per case and why there is none
    (:func:`_screening`), pinned to one BLAS thread and silent: the campaign's own checks say what is
    wrong with a case (the screening may run before them)."""
    with single_threaded(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _screening(campaign, loaders)


def _tables_job(campaign: Campaign, loaders) -> list:
    with single_threaded(), warnings.catch_warnings():    # the values a trial's process would make
        warnings.simplefilter("ignore")
        return campaign_tables(campaign, loaders[1])


def case_sensitivity(campaign: Campaign, loaders) -> str:
    """What moves the limit of the campaign's base landing — the screening's one-at-a-time sensitivity
    (:func:`boatland.freqdomain.sensitivity.sensitivity`, as ``boatland screen --sensitivity``) at the base's Tp,
    over the campaign's relative headings (its axis, else 180°, 135°, 90°), at its accepted risk (``[isee]
    accept`` per its access, else Grøtting 2015's best estimate per 30-min access) — as JSON for the store (``/sensitivity``), or
    ``{"unavailable": why}`` when the base cannot be screened (no spectral sea, no landing or thrust). Pinned
    to one BLAS thread, silent."""
    import json

    from boatland.errors import BoatlandInputError
    from boatland.freqdomain.landing import LandingSetup
    from boatland.freqdomain.sensitivity import DEFAULT_HEADINGS, sensitivity
    from boatland.landing.setup import Setup

    base = campaign.base
    parts = getattr(getattr(base.sea, "waves", None), "parts", None)
    if not parts or base.landing is None or base.thrust is None or base.fender is None:
        return json.dumps({"unavailable": "the base scenario has no spectral sea, landing, fender or thrust"})
    heads = campaign.axes.get("sea.relative_direction_deg") or DEFAULT_HEADINGS
    isee = campaign.method == "isee" and campaign.isee.accept is not None    # its accept is per its access
    accept, access = (campaign.isee.accept, campaign.access or 1800.0) if isee else ("best", 1800.0)
    with single_threaded(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            db = loaders[1](base)
            setup = Setup.of(base, db)
            study = sensitivity(db, LandingSetup.from_scenario(base, db, setup=setup), parts[0].Tp,
                                [float(h) for h in heads], accept=accept, sea=parts[0],
                                water_depth=getattr(setup.waves, "water_depth", None),
                                access_duration=access)
        except (BoatlandInputError, ValueError) as exc:
            return json.dumps({"unavailable": str(exc)})
    return json.dumps(study.as_dict())


class BackgroundWork:
    """What a campaign computes once beside its trials, in a process of its own started before its checks
    (on the core they leave idle): first the ω tables of the pile's scattered wave of every case
    (:func:`campaign_tables`, which the first case's preparation waits for), then the frequency-domain
    screening (:func:`_screening`) and the base's sensitivity (:func:`case_sensitivity`), read when the trials
    are done. Pinned to one BLAS thread like every
    trial, so its values are the ones the campaign's own process would make; if the process cannot give
    them, they are made here."""

    def __init__(self, campaign: Campaign, loaders):
        self.campaign, self.loaders = campaign, loaders
        self.pool = process_pool(1)
        self.futures = (self.pool.submit(_tables_job, campaign, loaders),      # one process: in this order
                        self.pool.submit(case_screening, campaign, loaders),
                        self.pool.submit(case_sensitivity, campaign, loaders))

    def tables(self) -> list:
        """The pile's tables of every case (:func:`campaign_tables`)."""
        try:
            return self.futures[0].result()
        except Exception:  # noqa: BLE001 — e.g. the process died: the campaign's own process makes them
            return _tables_job(self.campaign, self.loaders)

    def screening(self) -> tuple[np.ndarray, list[str]]:
        """The screening's P(slip) per case and why there is none (:func:`_screening`)."""
        try:
            return self.futures[1].result()
        except Exception:  # noqa: BLE001 — e.g. the process died: the campaign's own process computes it
            return case_screening(self.campaign, self.loaders)

    def sensitivity(self) -> str:
        """What moves the base's limit (:func:`case_sensitivity`), as JSON."""
        try:
            return self.futures[2].result()
        except Exception:  # noqa: BLE001 — e.g. the process died: the campaign's own process computes it
            return case_sensitivity(self.campaign, self.loaders)

    def close(self) -> None:
        """Stop the process now if it is still running (the campaign stopped early)."""
        if all(f.done() for f in self.futures):
            self.pool.shutdown(wait=True)
        else:
            kill_pool(self.pool)


def _screening(campaign: Campaign, loaders) -> tuple[np.ndarray, list[str]]:
    """The frequency-domain screening's P(slip within the access) per case (Wu 2014 as in Grøtting 2015
    §3.2.1, §3.4, eq. 3.38, Rayleigh; the improved landing — each contact on its own, the fender's
    normal and shear laws, the pile's scattered wave when the trials have it), computed from each case's
    own scenario and database: the prediction beside the Monte Carlo result (Grøtting 2015 Tables
    4.14–4.15). Returns the probabilities (NaN where none) and, per case, why there is none ("" where
    there is one)."""
    from boatland.freqdomain.landing import LandingSetup
    from boatland.freqdomain.screening import sea_response
    from boatland.landing.setup import Setup

    out = np.full(len(campaign.cases), math.nan)
    why = [""] * len(campaign.cases)
    dbs: dict = {}
    for case in campaign.cases:
        try:
            sc = campaign.base.replace(dict(case.values))
            parts = getattr(sc.sea.waves, "parts", None) if sc.sea is not None else None
            if not parts:
                why[case.index] = "no spectral sea (the screening needs spectral parts: " + ", ".join(s.label for s in SHAPES.values()) + ")"
                continue
            if sc.fender is None:
                why[case.index] = "no fender"
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                db = database_for(sc, dbs, loaders[1])
                setup = Setup.of(sc, db)
                landing = LandingSetup.from_scenario(sc, db, setup=setup)
                access = campaign.access if campaign.access is not None else \
                    sc.simulation.duration - exposure_start(sc)
                out[case.index] = sea_response(db, landing, parts, access_duration=access,
                                               water_depth=getattr(setup.waves, "water_depth", None)).p_access
        except Exception as exc:  # noqa: BLE001 — the report says why; the Monte Carlo stands
            why[case.index] = f"{type(exc).__name__}: {exc}"[:190]
    return out, why
