"""Run a campaign: every trial of the plan on local processes or a Dask cluster, into a resumable store.

Each trial is one :func:`boatland.trial.simulate.simulate` of the case's scenario with its seed; its
summary row goes to the :class:`~boatland.campaign.store.CampaignStore` as soon as it arrives. Trials
already in the store are skipped (resume). A failing trial is recorded with its message and never
stops the batch. Results do not depend on the executor, the number of workers or the order of
completion: each trial's inputs come only from the plan (seeds: :func:`boatland.campaign.plan.trial_seed`),
and rows are stored by trial number.

Executors: ``"local"`` — a pool of worker processes (default: one per core; one worker runs in
this process); ``"dask"`` — a ``distributed`` scheduler at ``scheduler`` (``tcp://host:port``).

Reproducible everywhere: every trial runs with BLAS/LAPACK pinned to one thread
(:func:`boatland.reproducible.single_threaded`), as Dask workers run by default, so a store is the
same bit for bit from 1 or N local workers, a Dask cluster, or machines with more cores.

Failed trials (an exception, NaN, a runaway; not a fender that slid off the landing, which is an
outcome) are stored with their reason and left out of
every probability; :func:`failures` lists them per case. Before any trial, every case's scenario gets
the checks ``boatland run`` makes (:func:`check_cases`).

Work done once per campaign, not per trial or worker: :func:`check_cases` makes each radiation memory
(IRFs and state-space fit) once; :func:`prepare_cases` compiles the kernel arrays of each case from it;
the ω tables of the pile's scattered wave the trials interpolate are made once for the whole campaign,
every wave direction of a layout in one pass (:func:`boatland.model.pile_diffraction.make_tables`);
every trial is shipped its case's :class:`CaseData` (local workers: with the task; Dask: one scattered
copy per case), so no worker makes either again. They are the values a worker would have made (the
same functions, pinned to one BLAS thread): the store is the same bit for bit. With several workers
the tables and then the frequency-domain screening are made in a process of its own
(:class:`BackgroundWork`), which starts before the checks, on the core they leave idle.

Local workers die with the campaign: each sets ``PR_SET_PDEATHSIG`` (Linux) and watches its parent's
pid, so neither SIGKILL nor SIGTERM of the campaign leaves workers running; a campaign stopped by an
error (e.g. the disk is full) cancels the trials still queued.
"""

from __future__ import annotations

import json
import math
import os
import signal
import sys
import threading
import time
import traceback
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from boatland import __version__
from boatland.campaign.labels import campaign_inputs
from boatland.campaign.plan import Campaign, TrialSpec, load_campaign, trial_seed
from boatland.campaign.stats import clopper_pearson, exponential_mean_interval
from boatland.campaign.store import INCIDENT_PREFIX, CampaignStore
from boatland.errors import BoatlandInputError
from boatland.integrate.cummins import OUTCOME_STATUSES
from boatland.model.motion import MotionArrays
from boatland.reproducible import single_threaded
from boatland.trial.simulate import exposure_start

__all__ = ["run_campaign", "execute_trial", "incident_names", "case_statistics", "check_cases", "prepare_cases",
           "CaseData", "completed", "failures", "start_background", "BackgroundWork"]

_CACHE: dict = {}   # per worker process: campaign, databases and radiation memories
_CHECKED: dict = {}  # per campaign process: what check_cases made, by (campaign digest, database loader)


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


def incident_names(campaign: Campaign) -> list[str]:
    """Incident definitions of the campaign: first slip, each slip distance, each roll limit, contact loss."""
    inc = campaign.base.incidents
    names = ["first slip"]
    names += [f"slip > {d:g} m" for d in (inc.slip_distance if inc else (0.1,))]
    names += [f"roll > {r:g}°" for r in (inc.roll_limit_deg if inc else ())]
    if campaign.base.fender is not None:
        names.append("contact loss")
    return names


def _context(source: str, loaders):
    load_scenario, load_database = loaders
    key = (source, loaders)
    if key not in _CACHE:
        campaign = load_campaign(source, load_scenario=load_scenario)
        _CACHE.clear()
        _CACHE[key] = {"campaign": campaign, "db": {}, "memory": {}, "checked": set()}
    return _CACHE[key]


def execute_trial(source: str, spec: TrialSpec, loaders, keep_dir: str | None = None,
                  shared: CaseData | None = None) -> dict:
    """Run one trial of the campaign file ``source`` and return its summary row (never raises for a
    failing trial: the row carries status −1 and the error).

    ``shared``: its case's :class:`CaseData` from :func:`prepare_cases` (the memory checked there). Without
    it the worker makes the radiation memory (once per worker), checks it (once per case) and compiles
    the kernel arrays and the pile's tables itself — the same values.
    """
    from boatland.model.pile_diffraction import remember_tables
    from boatland.trial.simulate import BlowUpError, check_radiation, prepare_memory, simulate

    wall0 = time.perf_counter()
    row = {"trial": spec.trial, "case": spec.case, "seed_index": spec.seed_index, "seed": spec.seed}
    pin = single_threaded()
    pin.__enter__()
    try:
        ctx = _context(source, loaders)
        campaign: Campaign = ctx["campaign"]
        names = incident_names(campaign)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            scenario = campaign.scenario_for(spec)
            dbkey = scenario.vessel.database_key
            if dbkey not in ctx["db"]:
                ctx["db"][dbkey] = loaders[1](scenario)
            db = ctx["db"][dbkey]
            if shared is not None:
                remember_tables(shared.tables)
                run = dict(arrays=shared.arrays)
            else:
                rad = scenario.radiation
                mkey = _memory_key(dbkey, rad)
                if mkey not in ctx["memory"]:
                    ctx["memory"][mkey] = prepare_memory(scenario, db)
                if spec.case not in ctx["checked"]:   # the memory damps this case's landed modes (once per case)
                    check_radiation(scenario, db, ctx["memory"][mkey], scenario.time_step(db))
                    ctx["checked"].add(spec.case)
                run = dict(memory=ctx["memory"][mkey])
            try:
                result = simulate(scenario, db, **run)
            except BlowUpError as exc:
                result = exc.result
        row.update(_summary_row(result, result.exposure_from, scenario.simulation.duration, names))
        if keep_dir is not None and spec.trial in campaign.keep_series:
            Path(keep_dir).mkdir(parents=True, exist_ok=True)
            result.to_hdf5(Path(keep_dir) / f"trial_{spec.trial:06d}.h5")
    except Exception as exc:  # a failing trial is recorded, never aborts the campaign
        last = traceback.extract_tb(exc.__traceback__)[-1] if exc.__traceback__ else None
        where = f" ({Path(last.filename).name}:{last.lineno})" if last else ""
        row.update({"status": -1, "message": f"{type(exc).__name__}: {exc}{where}"[:200]})
    finally:
        pin.__exit__(None, None, None)
    row["wall_time"] = time.perf_counter() - wall0
    return row


def _memory_key(dbkey: str, rad) -> tuple:
    """The radiation memory a scenario needs: its database and radiation settings."""
    return (dbkey, rad.method, rad.memory, rad.tail, rad.taper)


def _first_trial(campaign: Campaign, case: int) -> TrialSpec:
    return TrialSpec(case * campaign.seeds, case, 0, trial_seed(campaign.master_seed, 0))


def check_cases(campaign: Campaign, load_database) -> list[str]:
    """The checks ``boatland run`` makes, for every case's scenario, before any trial: the scenario
    against its database (:meth:`Scenario.check_against`: dt against the fender contact, the fender on
    the bow, ...), the limits of :func:`boatland.model.limits.scenario_problems` and the radiation memory
    at the landed modes (:func:`boatland.model.landed.check_memory`).

    Returns the warnings (one line each, naming the case); raises :class:`SpecError` with every problem
    of every case (key paths prefixed by the case).

    The radiation memories it makes are the ones the trials use (:func:`prepare_cases`); they and the
    outcome are kept in this process for the same campaign (its :meth:`~Campaign.digest`: files and their
    contents) and loader, so checking again (``run_campaign`` after the CLI) costs nothing.
    """
    return list(_checked(campaign, load_database)["warnings"])


def _checked(campaign: Campaign, load_database) -> dict:
    """:func:`check_cases`'s work, kept: ``{"warnings", "dbs", "memories"}``."""
    key = (campaign.digest(), load_database)
    if key in _CHECKED:
        return _CHECKED[key]
    from boatland.model.landed import check_memory
    from boatland.model.limits import scenario_problems
    from boatland.model.tomlspec import SpecError
    from boatland.trial.simulate import prepare_memory

    problems, warns, dbs = [], [], {}
    memories: dict = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for case in campaign.cases:
            sc = campaign.scenario_for(_first_trial(campaign, case.index))
            dbkey = sc.vessel.database_key
            if dbkey not in dbs:
                dbs[dbkey] = load_database(sc)
            db = dbs[dbkey]
            check = sc.check_against(db)
            where = f"case {case.index} ({case.label() or 'base'})"
            found = list(check.problems) + [p for p in scenario_problems(sc, db) if p not in check.problems]
            if not found and db.M is not None:     # the radiation memory damps this case's landed modes
                mkey = _memory_key(dbkey, sc.radiation)
                if mkey not in memories:
                    memories[mkey] = prepare_memory(sc, db)    # pinned to one BLAS thread, as in a trial
                mc = check_memory(sc, db, memories[mkey], sc.time_step(db))
                found += list(mc.problems)
                warns += [f"{where}: {k}: {m}" for k, m in mc.warnings]
            problems += [(f"{where}: {k}", m) for k, m in found]
            warns += [f"{where}: {k}: {m}" for k, m in check.warnings]
    if problems:
        raise SpecError(campaign.source, problems)
    _CHECKED.clear()                               # one campaign at a time: bounded memory
    _CHECKED[key] = {"warnings": tuple(dict.fromkeys(warns)), "dbs": dbs, "memories": memories}
    return _CHECKED[key]


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
    prepared = _CasePreparation(campaign, load_database)
    return {case: data for case in (range(len(campaign.cases)) if cases is None else cases)
            if (data := prepared.get(case)) is not None}


class _CasePreparation:
    """case → :class:`CaseData` (or None), made the first time it is asked for — when the first trial of the
    case is handed to the executor, so that the workers start on the first case while the next ones are
    prepared. Kernel arrays are compiled once per radiation memory and time step; the pile's tables of
    every case are made together when the first case is (:func:`_campaign_tables`), or taken from
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
                    from boatland.model.pile_diffraction import remember_tables

                    self.tables_in = True
                    remember_tables(self.background.tables() if self.background is not None else
                                    _campaign_tables(self.campaign, self.load_database, self.checked["dbs"]))
                try:
                    self.cases[case] = self._prepare(case)
                except Exception:  # noqa: BLE001 — its trials meet it again and record it
                    self.cases[case] = None
        return self.cases[case]

    def _prepare(self, case: int) -> CaseData:
        from boatland.trial.simulate import motion_arrays, pile_tables

        sc = self.campaign.scenario_for(_first_trial(self.campaign, case))
        dbkey = sc.vessel.database_key
        db = self.checked["dbs"][dbkey]
        mkey = _memory_key(dbkey, sc.radiation)
        akey = (mkey, sc.time_step(db))
        if akey not in self.arrays:
            self.arrays[akey] = motion_arrays(sc, db, self.checked["memories"][mkey])
        return CaseData(arrays=self.arrays[akey], tables=tuple(pile_tables(sc, db)))


def _campaign_tables(campaign: Campaign, load_database, dbs: dict | None = None) -> list:
    """The ω tables of the pile's scattered wave of every case (:func:`boatland.trial.simulate.pile_tables`),
    the directions of each database and layout made together
    (:func:`boatland.model.pile_diffraction.make_tables`; three directions of the ctv24: 1.4 s instead of
    2.6 s). None at all when there are more than a process keeps (then each case makes its own), and none
    for a case whose tables fail: its own preparation meets the error again."""
    from boatland.model.pile_diffraction import TABLE_CACHE_SIZE, make_tables
    from boatland.trial.simulate import pile_table_request

    requests: dict = {}
    dbs = {} if dbs is None else dict(dbs)      # databases by key, loaded where missing
    for case in campaign.cases:
        try:
            sc = campaign.scenario_for(_first_trial(campaign, case.index))
            dbkey = sc.vessel.database_key
            if dbkey not in dbs:
                dbs[dbkey] = load_database(sc)
            request = pile_table_request(sc, dbs[dbkey])
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


def completed(table: np.ndarray) -> np.ndarray:
    """Rows of trials that ran to an outcome: completed, or ended when the fender slid off the landing
    (:data:`boatland.integrate.cummins.OUTCOME_STATUSES`); the rest failed (an exception, NaN, a runaway)."""
    return np.isin(table["status"], OUTCOME_STATUSES) if table.size else np.zeros(0, bool)


def failures(campaign: Campaign, table: np.ndarray) -> dict[int, list[tuple[int, str]]]:
    """Failed trials (not :func:`completed`) per case: case → [(trial, reason)]."""
    out: dict[int, list[tuple[int, str]]] = {}
    for r in table[~completed(table)] if table.size else table:
        msg = r["message"].decode(errors="replace") if isinstance(r["message"], bytes) else str(r["message"])
        out.setdefault(int(r["case"]), []).append((int(r["trial"]), msg or f"status {int(r['status'])}"))
    return out


def _summary_row(result, t0: float, duration: float, names: list[str]) -> dict:
    s = result.summary()
    nan = math.nan
    rel = lambda t: nan if t is None else max(0.0, float(t) - t0)  # noqa: E731
    row = {
        "status": int(result.status), "message": result.message[:200],
        "exposure": max(0.0, float(result.t[-1]) - t0),
        "time_to_first_slip": rel(s["time_to_first_slip"]),
        "slip_events": int(s["slip_events"]),
        "max_slip_distance": float(s["max_slip_distance"]), "max_single_slide": float(s["max_single_slide"]),
        "max_normal_force": nan if s["max_normal_force"] is None else float(s["max_normal_force"]),
        "min_normal_force": nan if s["min_normal_force_in_contact"] is None else float(s["min_normal_force_in_contact"]),
        "max_roll_deg": float(np.degrees(result.peak_motions[3])),
        "max_pitch_deg": float(np.degrees(result.peak_motions[4])),
        "contact_fraction": float(s["contact_fraction"]),
    }
    inc = s["incidents"]
    for name in names:
        t = row["time_to_first_slip"] if name == "first slip" else rel(inc.get(name))
        row[INCIDENT_PREFIX + name] = t
    return row


def run_campaign(campaign: Campaign, store_path: str | Path, *, loaders, executor: str = "local",
                 workers: int | None = None, scheduler: str | None = None, progress=None,
                 connect_timeout: float = 10.0, background: "BackgroundWork | None" = None) -> CampaignStore:
    """Run every trial of ``campaign`` not yet in the store at ``store_path``.

    Parameters
    ----------
    campaign : Campaign
    store_path : path
        The HDF5 store (created, or resumed when it holds this campaign's trials).
    loaders : (callable, callable)
        ``(load_scenario(path) -> Scenario, load_database(scenario) -> HydroDB)``: top-level functions
        (they are sent to worker processes); the edge passes its file loaders.
    executor : {"local", "dask"}
    workers : int, optional
        Local worker processes (default: all cores).
    scheduler : str, optional
        Address of a Dask scheduler (``tcp://host:port``) for ``executor="dask"``.
    progress : callable, optional
        ``progress(done, total)`` after each trial.
    background : BackgroundWork, optional
        The pile's tables and the frequency-domain screening already started by :func:`start_background`
        for this campaign (the CLI starts it before its checks, on the core they leave idle); closed here.
        Default: started here (in a process of its own when the trials run in other processes).

    Returns
    -------
    CampaignStore
        Finished: every row and the per-case statistics written.
    """
    try:
        names = incident_names(campaign)
        header = {
            "campaign": campaign.name, "campaign_digest": campaign.digest(),
            "campaign_file": Path(campaign.source).read_text(encoding="utf-8"),
            "plan": _plan_json(campaign), "n_trials": campaign.n_trials, "incidents": "\n".join(names),
            "inputs": json.dumps(campaign_inputs(campaign), default=float),   # for the report's titles
        }
        if executor == "dask":
            _check_scheduler_address(scheduler)
        check_cases(campaign, loaders[1])
        store = CampaignStore.open(store_path, header, names)
        try:
            todo = [s for s in campaign.trials() if s.trial not in store.done()]
            total = campaign.n_trials
            if progress:
                progress(total - len(todo), total)
            keep = str(store.series_dir) if campaign.keep_series else None
            source = str(Path(campaign.source).resolve())
            if background is None and todo:
                background = start_background(campaign, loaders, executor, workers)
            shared = _CasePreparation(campaign, loaders[1], background)   # a case's data when its first trial is sent
            if todo and executor == "local":        # forked workers inherit the campaign and databases
                _context(source, loaders)["db"].update(shared.checked["dbs"])
            rows = _execute(todo, (source, loaders, keep), executor, workers, scheduler, connect_timeout, shared)
            try:
                for row in rows:
                    store.add(row)
                    if progress:
                        progress(len(store.rows), total)
            finally:
                rows.close()               # an error above cancels the queued trials and stops the workers
            p_fd, why = background.screening() if background is not None else _screening_job(campaign, loaders)
            store.finish(case_statistics(campaign, store.table(), names, screening=p_fd, screening_notes=why))
        finally:
            store.close()
    finally:
        if background is not None:          # stopped now if the campaign stopped early
            background.close()
    return store


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


def _screening_job(campaign: Campaign, loaders) -> tuple[np.ndarray, list[str]]:
    # silent: the campaign's own checks say what is wrong with a case (the screening may run before them)
    with single_threaded(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _screening(campaign, loaders)


def _tables_job(campaign: Campaign, loaders) -> list:
    with single_threaded(), warnings.catch_warnings():    # the values a trial's process would make
        warnings.simplefilter("ignore")
        return _campaign_tables(campaign, loaders[1])


class BackgroundWork:
    """What a campaign computes once beside its trials, in a process of its own started before its checks
    (on the core they leave idle): first the ω tables of the pile's scattered wave of every case
    (:func:`_campaign_tables`, which the first case's preparation waits for), then the frequency-domain
    screening (:func:`_screening`, read when the trials are done). Pinned to one BLAS thread like every
    trial, so its values are the ones the campaign's own process would make; if the process cannot give
    them, they are made here."""

    def __init__(self, campaign: Campaign, loaders):
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor

        self.campaign, self.loaders = campaign, loaders
        method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
        self.pool = ProcessPoolExecutor(max_workers=1, mp_context=multiprocessing.get_context(method),
                                        initializer=_worker_init, initargs=(os.getpid(),))
        self.futures = (self.pool.submit(_tables_job, campaign, loaders),      # one process: in this order
                        self.pool.submit(_screening_job, campaign, loaders))

    def tables(self) -> list:
        """The pile's tables of every case (:func:`_campaign_tables`)."""
        try:
            return self.futures[0].result()
        except Exception:  # noqa: BLE001 — e.g. the process died: the campaign's own process makes them
            return _tables_job(self.campaign, self.loaders)

    def screening(self) -> tuple[np.ndarray, list[str]]:
        """The screening's P(slip) per case and why there is none (:func:`_screening`)."""
        try:
            return self.futures[1].result()
        except Exception:  # noqa: BLE001 — e.g. the process died: the campaign's own process computes it
            return _screening_job(self.campaign, self.loaders)

    def close(self) -> None:
        """Stop the process now if it is still running (the campaign stopped early)."""
        procs = [] if all(f.done() for f in self.futures) else list(getattr(self.pool, "_processes", {}).values())
        self.pool.shutdown(wait=not procs, cancel_futures=True)
        for proc in procs:
            proc.kill()
        for proc in procs:
            proc.join(5.0)


def _screening(campaign: Campaign, loaders) -> tuple[np.ndarray, list[str]]:
    """The frequency-domain screening's P(slip within the access) per case (Wu 2014 as in Grøtting 2015
    §3.2.1, §3.4, eq. 3.38, Rayleigh; the improved landing — each contact on its own, the fender's
    normal and shear laws, the pile's scattered wave when the trials have it), computed from each case's
    own scenario and database: the prediction beside the Monte Carlo result (Grøtting 2015 Tables
    4.14–4.15). Returns the probabilities (NaN where none) and, per case, why there is none ("" where
    there is one)."""
    from boatland.freqdomain.screening import LandingSetup, sea_response

    out = np.full(len(campaign.cases), math.nan)
    why = [""] * len(campaign.cases)
    dbs: dict = {}
    for case in campaign.cases:
        try:
            sc = campaign.base.replace(dict(case.values))
            parts = getattr(sc.sea.waves, "parts", None) if sc.sea is not None else None
            if not parts:
                why[case.index] = "no spectral sea (the screening needs JONSWAP/PM/TMA parts)"
                continue
            if sc.fender is None:
                why[case.index] = "no fender"
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                key = sc.vessel.database_key
                if key not in dbs:
                    dbs[key] = loaders[1](sc)
                db = dbs[key]
                setup = LandingSetup.from_scenario(sc, db)
                access = campaign.access if campaign.access is not None else \
                    sc.simulation.duration - exposure_start(sc)
                out[case.index] = sea_response(db, setup, parts, access_duration=access,
                                               water_depth=getattr(sc.wave_model(db), "water_depth", None)).p_access
        except Exception as exc:  # noqa: BLE001 — the report says why; the Monte Carlo stands
            why[case.index] = f"{type(exc).__name__}: {exc}"[:190]
    return out, why


def _execute(todo, args, executor, workers, scheduler, connect_timeout, shared=None):
    """Run the trials ``todo`` and yield their rows as they finish; ``shared``: case → :class:`CaseData`
    (``shared.get(case)``: a dict from :func:`prepare_cases`, or made on demand), shipped with each trial
    of the case."""
    source, loaders, keep = args
    shared = {} if shared is None else shared
    if not todo:
        return
    if executor == "dask":
        yield from _execute_dask(todo, args, scheduler, connect_timeout, shared)
        return
    if executor != "local":
        raise BoatlandInputError(f"executor must be 'local' or 'dask', got {executor!r}")
    n = workers or os.cpu_count() or 1
    if n == 1:
        for spec in todo:
            yield execute_trial(source, spec, loaders, keep, shared.get(spec.case))
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    # fork where there is one (Linux): no re-import per worker and no `if __name__ == "__main__"`
    # guard needed in a user's script; the workers inherit the compiled kernels' cache state
    method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    pool = ProcessPoolExecutor(max_workers=n, mp_context=multiprocessing.get_context(method),
                               initializer=_worker_init, initargs=(os.getpid(),))
    futures = []
    try:
        yield from _submitted(todo, futures, lambda spec: pool.submit(execute_trial, source, spec, loaders, keep,
                                                                      shared.get(spec.case)))
    except BaseException:          # the consumer stopped (an error, Ctrl-C): cancel, stop the workers now
        for fut in futures:
            fut.cancel()
        procs = list(getattr(pool, "_processes", {}).values())
        pool.shutdown(wait=False, cancel_futures=True)
        for p in procs:
            p.kill()
        for p in procs:
            p.join(5.0)
        raise
    pool.shutdown(wait=True)


def _submitted(todo, futures: list, submit):
    """Submit every trial of ``todo`` (``submit(spec)`` → a future, appended to ``futures``) and yield the
    rows as they finish — those that finish while later trials are still being submitted (a case's data
    is made when its first trial is sent) as well."""
    import queue

    finished: queue.SimpleQueue = queue.SimpleQueue()
    handed = 0
    for spec in todo:
        fut = submit(spec)
        futures.append(fut)
        fut.add_done_callback(finished.put)
        while not finished.empty():
            handed += 1
            yield finished.get().result()
    for _ in range(len(futures) - handed):
        yield finished.get().result()


def _worker_init(parent: int) -> None:
    """In each local worker: die with the campaign process, however it ends (SIGKILL included)."""
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(1, int(signal.SIGKILL), 0, 0, 0)          # PR_SET_PDEATHSIG
        except (OSError, AttributeError):
            pass
    if os.getppid() != parent:        # the parent died before the line above
        os._exit(1)
    threading.Thread(target=_watch_parent, args=(parent,), name="boatland-watch-parent", daemon=True).start()


def _watch_parent(parent: int, every: float = 1.0) -> None:
    """Fallback where PR_SET_PDEATHSIG does not exist: leave when the parent process is gone."""
    while True:
        time.sleep(every)
        if os.getppid() != parent:
            os._exit(1)


def _check_scheduler_address(scheduler: str | None) -> None:
    """A Dask scheduler address must be ``tcp://host:port`` (or tls/ws/wss/ucx/inproc)."""
    from urllib.parse import urlparse

    if not scheduler:
        raise BoatlandInputError("the Dask executor needs a scheduler address (--scheduler tcp://host:port)")
    try:
        u = urlparse(scheduler)
        port = u.port
    except ValueError:
        port = None
        u = None
    if u is None or u.scheme not in ("tcp", "tls", "ws", "wss", "ucx") or not u.hostname or port is None \
            or u.path not in ("", "/") or u.query or u.fragment:
        raise BoatlandInputError(f"--scheduler {scheduler}: not a scheduler address; expected "
                                 "tcp://HOST:PORT (e.g. tcp://127.0.0.1:8786)")


def _execute_dask(todo, args, scheduler, connect_timeout, shared):
    source, loaders, keep = args
    if not scheduler:
        raise BoatlandInputError("the Dask executor needs a scheduler address (--scheduler tcp://host:port)")
    try:
        from distributed import Client
    except ImportError:
        raise BoatlandInputError("the Dask executor needs dask.distributed: pip install 'dask[distributed]'") from None
    try:
        client = Client(scheduler, timeout=connect_timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise BoatlandInputError(f"--scheduler {scheduler}: no Dask scheduler answered within "
                                 f"{connect_timeout:g} s ({type(exc).__name__}); is it running?") from None
    try:
        data: dict = {}                           # one scattered copy of each case's data

        def submit(spec):
            if spec.case not in data:
                d = shared.get(spec.case)
                data[spec.case] = None if d is None else client.scatter(d, hash=False)
            return client.submit(execute_trial, source, spec, loaders, keep, data[spec.case], pure=False)

        yield from _submitted(todo, [], submit)
    finally:
        client.close()


def _plan_json(campaign: Campaign) -> str:
    import json

    return json.dumps({"name": campaign.name, "scenario": str(campaign.scenario_path), "seeds": campaign.seeds,
                       "master_seed": campaign.master_seed, "axes": campaign.axes,
                       "cases": [c.values for c in campaign.cases], "boatland": __version__}, default=str)


def case_statistics(campaign: Campaign, table: np.ndarray, names: list[str], confidence: float = 0.95,
                    screening: np.ndarray | None = None, screening_notes: list[str] | None = None) -> np.ndarray:
    """Per case and incident definition: P(incident within the access) with its Clopper–Pearson
    interval and the mean time to the incident with its exponential (χ²) interval; failed trials
    (status an exception, NaN, a runaway) are left out and counted. ``screening``: the frequency-domain P(slip
    within the access) per case, stored beside them (column ``screening: P(slip)``), and why it is
    missing where it is (``screening: note``)."""
    cases = campaign.cases
    fields = [("case", "i8"), ("label", "S200"), ("trials", "i8"), ("failed", "i8"), ("screening: P(slip)", "f8"),
              ("screening: note", "S200")]
    for c in campaign.axes:
        fields.append((f"axis: {c}", "f8"))
    for n in names:
        fields += [(f"{n}: count", "i8"), (f"{n}: P", "f8"), (f"{n}: P lo", "f8"), (f"{n}: P hi", "f8"),
                   (f"{n}: mean time", "f8"), (f"{n}: mean lo", "f8"), (f"{n}: mean hi", "f8")]
    out = np.zeros(len(cases), dtype=fields)
    for i, case in enumerate(cases):
        rows = table[table["case"] == case.index] if table.size else table
        ok = rows[completed(rows)] if rows.size else rows
        out[i]["case"] = case.index
        out[i]["label"] = case.label().encode()[:200]
        out[i]["trials"] = len(rows)
        out[i]["failed"] = len(rows) - len(ok)
        out[i]["screening: P(slip)"] = math.nan if screening is None else screening[i]
        out[i]["screening: note"] = ("" if screening_notes is None else screening_notes[i]).encode()[:200]
        for c, v in case.values.items():
            out[i][f"axis: {c}"] = float(v) if isinstance(v, (int, float)) else math.nan
        for n in names:
            t = ok[INCIDENT_PREFIX + n] if ok.size else np.zeros(0)
            hit = np.isfinite(t)
            p, lo, hi = clopper_pearson(int(hit.sum()), len(t), confidence)
            m, mlo, mhi = exponential_mean_interval(t, ok["exposure"] if ok.size else 0.0, confidence)
            out[i][f"{n}: count"] = int(hit.sum())
            out[i][f"{n}: P"], out[i][f"{n}: P lo"], out[i][f"{n}: P hi"] = p, lo, hi
            out[i][f"{n}: mean time"], out[i][f"{n}: mean lo"], out[i][f"{n}: mean hi"] = m, mlo, mhi
    return out
