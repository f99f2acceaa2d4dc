"""Run a campaign: every trial of the plan on local processes or a Dask cluster, into a resumable store.

Each trial is one :func:`boatland.trial.simulate.simulate` of the case's scenario with its seed; its
summary row goes to the :class:`~boatland.campaign.store.CampaignStore` as soon as it arrives. Trials
already in the store are skipped (resume). A failing trial is recorded with its message and never
stops the batch. Results do not depend on the executor, the number of workers or the order of
completion: each trial's inputs come only from the plan (seeds: :func:`boatland.campaign.plan.trial_seed`),
and rows are stored by trial number.

Executors (:class:`boatland.campaign.executor.Executor`): ``"local"`` — a pool of worker processes
(default: one per core; one worker runs in this process); ``"dask"`` — a ``distributed`` scheduler at
``scheduler`` (``tcp://host:port``).

Reproducible everywhere: every trial runs with BLAS/LAPACK pinned to one thread
(:func:`boatland.reproducible.single_threaded`), as Dask workers run by default, so a store is the
same bit for bit from 1 or N local workers, a Dask cluster, or machines with more cores.

Failed trials (an exception, NaN, a runaway; not a fender that slid off the landing, which is an
outcome) are stored with their reason and left out of
every probability; :func:`failures` lists them per case. Before any trial, every case's scenario gets
the checks ``boatland run`` makes (:func:`boatland.campaign.prepare.check_cases`).

What a campaign does once — the checks, each case's kernel arrays and the pile's tables (shipped with its
trials: local workers with the task, Dask one scattered copy per case), the frequency-domain screening —
is :mod:`boatland.campaign.prepare`. A campaign stopped by an error (e.g. the disk is full) cancels the
trials still queued and stops its workers.
"""

from __future__ import annotations

import json
import math
import time
import traceback
import warnings
from pathlib import Path

import numpy as np

from boatland.campaign.executor import Executor, Shared, check_scheduler_address
from boatland.campaign.labels import campaign_inputs
from boatland.campaign.plan import Campaign, TrialSpec, plan_json
from boatland.campaign.prepare import (BackgroundWork, CaseData, CasePreparation, case_screening, case_sensitivity,
                                       check_cases, checked_inputs, database_for, memory_key, start_background,
                                       worker_context)
from boatland.campaign.stats import clopper_pearson, exponential_mean_interval
from boatland.campaign.store import INCIDENT_PREFIX, CampaignStore
from boatland.integrate.cummins import OUTCOME_STATUSES
from boatland.reproducible import single_threaded
from boatland.trial.incidents import campaign_incidents, parse_incident

__all__ = ["run_campaign", "execute_trial", "incident_names", "case_statistics", "completed", "failures",
           "summary_row"]


def incident_names(campaign: Campaign) -> list[str]:
    """Names of the campaign's incident definitions, its store's columns
    (:func:`boatland.trial.incidents.campaign_incidents`): first slip, each slip distance, each roll
    limit, contact loss."""
    return [d.name for d in campaign_incidents(campaign.base.incidents, campaign.base.fender is not None)]


def _db_arg(campaign: Campaign, spec, dbs: dict) -> Shared:
    """The database of ``spec``'s case as a :class:`Shared` argument (scattered once per database)."""
    key = campaign.scenario_for(spec).vessel.database_key
    return Shared(("db", key), (key, dbs[key]))


def execute_trial(campaign: Campaign, spec: TrialSpec, loaders, keep_dir: str | None = None,
                  shared: CaseData | None = None, db: tuple | None = None) -> dict:
    """Run one trial of ``campaign`` and return its summary row (never raises for a failing trial: the row
    carries status −1 and the error).

    ``shared``: its case's :class:`~boatland.campaign.prepare.CaseData` from
    :func:`boatland.campaign.prepare.prepare_cases` (the memory checked there). Without
    it the worker makes the radiation memory (once per worker), checks it (once per case) and compiles
    the kernel arrays and the pile's tables itself — the same values. ``db``: ``(key, database)`` of the case,
    as the campaign read it (a Dask worker never reads the database file; local workers inherit it).
    """
    from boatland.checks.memory import check_radiation
    from boatland.landing.setup import Setup
    from boatland.sea.pile import remember_tables
    from boatland.trial.simulate import BlowUpError, simulate

    wall0 = time.perf_counter()
    row = {"trial": spec.trial, "case": spec.case, "seed_index": spec.seed_index, "seed": spec.seed}
    pin = single_threaded()
    pin.__enter__()
    try:
        ctx = worker_context(campaign, loaders)
        if db is not None:                   # (key, database) read once by the campaign: never the file again
            ctx["db"].setdefault(*db)
        names = incident_names(campaign)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            scenario = campaign.scenario_for(spec)
            db = database_for(scenario, ctx["db"], loaders[1])
            dbkey = scenario.vessel.database_key
            setup = Setup.of(scenario, db)
            if shared is not None:
                remember_tables(shared.tables)
                run = dict(arrays=shared.arrays)
            else:
                rad = scenario.radiation
                mkey = memory_key(dbkey, rad)
                if mkey not in ctx["memory"]:
                    ctx["memory"][mkey] = setup.memory()
                if spec.case not in ctx["checked"]:   # the memory damps this case's landed modes (once per case)
                    check_radiation(setup, ctx["memory"][mkey])
                    ctx["checked"].add(spec.case)
                run = dict(memory=ctx["memory"][mkey])
            try:
                result = simulate(scenario, db, setup=setup, **run)
            except BlowUpError as exc:
                result = exc.result
        row.update(summary_row(result, result.exposure_from, scenario.simulation.duration, names))
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


def summary_row(result, t0: float, duration: float, names: list[str]) -> dict:
    """The store row of a trial (:data:`boatland.campaign.store.ROW_FIELDS` and one column per incident
    definition of ``names``): times relative to ``t0``, the start of the exposure (0 for an incident
    before it)."""
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
    inc = s["incidents"]                  # the trial's own definitions, found by the summary
    for name in names:
        row[INCIDENT_PREFIX + name] = rel(inc[name] if name in inc else parse_incident(name).first_time(result))
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
        if executor == "dask":
            check_scheduler_address(scheduler)
        check_cases(campaign, loaders[1])
        digest, digests, dbs = checked_inputs(campaign, loaders[1])    # of what the trials run on
        header = {
            "campaign": campaign.name, "campaign_digest": digest, "input_digests": json.dumps(digests),
            "campaign_file": campaign.text,
            "plan": plan_json(campaign), "n_trials": campaign.n_trials, "incidents": "\n".join(names),
            "inputs": json.dumps(campaign_inputs(campaign), default=float),   # for the report's titles
        }
        store = CampaignStore.open(store_path, header, names)
        try:
            todo = [s for s in campaign.trials() if s.trial not in store.done()]
            total = campaign.n_trials
            if progress:
                progress(total - len(todo), total)
            keep = str(store.series_dir) if campaign.keep_series else None
            if background is None and todo:
                background = start_background(campaign, loaders, executor, workers)
            shared = CasePreparation(campaign, loaders[1], background)   # a case's data when its first trial is sent
            if todo and executor == "local":        # forked workers inherit the campaign and databases
                worker_context(campaign, loaders)["db"].update(dbs)
            if todo:
                with Executor(executor, workers, scheduler, connect_timeout) as ex:
                    plan = Shared("campaign", campaign)     # to a Dask cluster once
                    dask = executor == "dask"               # its workers get the databases read here, once each
                    rows = ex.map(execute_trial, ((plan, spec, loaders, keep, Shared(spec.case, shared.get(spec.case)),
                                                   _db_arg(campaign, spec, dbs) if dask else None)
                                                  for spec in todo))
                    try:
                        for row in rows:
                            store.add(row)
                            if progress:
                                progress(len(store.rows), total)
                    finally:
                        rows.close()       # an error above cancels the queued trials and stops the workers
            p_fd, why = background.screening() if background is not None else case_screening(campaign, loaders)
            sens = background.sensitivity() if background is not None else case_sensitivity(campaign, loaders)
            store.finish(case_statistics(campaign, store.table(), names, screening=p_fd, screening_notes=why),
                         {"sensitivity": sens})
        finally:
            store.close()
    finally:
        if background is not None:          # stopped now if the campaign stopped early
            background.close()
    return store


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
