"""``boatland campaign``: a Monte Carlo slip-probability campaign into a resumable store."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from boatland.cli.common import campaign_setting, shipped_or_path
from boatland.cli.guard import in_range, integer
from boatland.outputs import Output, check_outputs

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    camp = sub.add_parser(
        "campaign", help="Monte Carlo slip-probability campaign: many trials over a sweep, into a resumable store",
        description="Run every trial of a campaign file (a base scenario, axes to sweep, N seeds per case) on "
                    "local worker processes or a Dask cluster. Results go to an HDF5 store as they arrive; "
                    "running the same command again resumes where it stopped (no trial lost or run twice). "
                    "Example: boatland campaign scenarios/campaigns/demo.toml")
    camp.add_argument("campaign", type=shipped_or_path("campaign"),
                      help="campaign file (TOML) or the name of a shipped one: demo, isee_rare, table414, … "
                           "(scenarios/campaigns/)")
    camp.add_argument("--set", type=campaign_setting, action="append", default=[], metavar="KEY=VALUE",
                      dest="settings",
                      help="change the campaign as its file would, validated the same way (repeatable): --set seeds=2 "
                           "--set access=600; the base scenario's keys under set. (--set set.thrust.force=100e3), an "
                           "axis under axes. (--set axes.sea.Hs=[0.5,1.0]). The store records the changed campaign")
    camp.add_argument("-o", "--output", type=Path, help="store (HDF5; default: <campaign name>.h5 here)")
    camp.add_argument("--workers", type=integer(1, 4096), help="local worker processes (default: all cores)")
    camp.add_argument("--scheduler", metavar="URL", help="run on a Dask scheduler (tcp://host:port) instead")
    camp.add_argument("--report", type=Path, metavar="DIR", help="also write the report into DIR at the end")
    camp.add_argument("--allow-failures", action="store_true",
                      help="exit 0 even when trials failed (they are always reported and left out of the statistics)")
    camp.add_argument("--method", choices=("monte-carlo", "isee"),
                      help="override the campaign file's method: monte-carlo (N seeds per case) or isee (importance "
                           "sampling of the first slip: rare slips and the limiting Hs at an accepted risk, "
                           "settings in the file's [isee])")
    camp.add_argument("--save-worst", type=integer(0, 1000), default=0, metavar="N",
                      help="isee: run the N heaviest samples again with their run logs (MCAP, 'boatland replay' for "
                           "Rerun) into <store>.worst/")
    camp.add_argument("--target", type=in_range(0.0, 1.0, hi_open=True), default=0.1,
                      help="accepted probability of the incident within the access, for the limiting Hs of the "
                           "summary and --report (default 0.1)")
    camp.add_argument("--width", type=in_range(0.0, 1.0, hi_open=True), default=0.2,
                      help="width asked of the 95 %% interval of P: the summary says how many seeds that needs "
                           "(default 0.2)")
    camp.add_argument("--json", action="store_true",
                      help="print the outcome (trials, failures, the decision table) as JSON instead of text")
    camp.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.campaign import load_campaign, run_campaign
    from boatland.campaign.report import REPORT_FILES, write_report
    from boatland.campaign.prepare import check_cases, start_background
    from boatland.campaign.runner import failures
    from boatland.checks.files import load, resolve_database
    from boatland.cli.common import check_fits_in_memory
    from boatland.landing.setup import Setup

    if args.scheduler:
        from boatland.campaign.executor import check_scheduler_address

        check_scheduler_address(args.scheduler)
    import warnings

    with warnings.catch_warnings(record=True) as caught:     # shown as one line each once the file is good
        warnings.simplefilter("always")
        campaign = load_campaign(args.campaign, load_scenario=load, changes=dict(args.settings), changed_by="--set ")
        if args.method:
            campaign = campaign.with_method(args.method)
    for w in dict.fromkeys(str(w.message) for w in caught):
        print(f"warning: {w}", file=sys.stderr)
    store = args.output or Path(f"{campaign.name}.h5")
    side = [store.with_name(store.name + s) for s in (".journal", ".lock", ".series")]
    isee = campaign.method == "isee"
    if args.save_worst and not isee:
        from boatland.errors import BoatlandInputError

        raise BoatlandInputError("--save-worst: only with method isee (a Monte Carlo campaign keeps trials with "
                                 "[store] keep_series)")
    worst_dir = store.with_name(store.name + ".worst") if args.save_worst else None
    check_outputs([Output("-o", store), *[Output("-o (its side file)", p) for p in side],
                   Output("--report", args.report, "folder", REPORT_FILES),
                   Output("--save-worst", worst_dir, "folder")], campaign.input_files())
    workers = 1 if args.scheduler else (args.workers or os.cpu_count() or 1)
    # the pile's tables and the frequency-domain screening need none of the checks below: started first,
    # they run on the core the checks leave idle (stopped if they refuse the campaign)
    background = None if isee else start_background(campaign, (load, resolve_database),
                                                    "dask" if args.scheduler else "local", args.workers)
    try:
        for w in check_cases(campaign, resolve_database):
            print(f"warning: {w}", file=sys.stderr)
        longest = max((campaign.scenario_for(campaign.trials()[c * campaign.seeds])
                       for c in range(len(campaign.cases))), key=lambda s: s.simulation.duration)
        check_fits_in_memory(Setup.of(longest, resolve_database(longest)), flag=f"{args.campaign}: duration",
                             copies=min(workers, campaign.n_trials))
    except BaseException:
        if background is not None:
            background.close()
        raise
    where = f"Dask scheduler {args.scheduler}" if args.scheduler else \
        f"{args.workers or os.cpu_count()} local worker process(es)"
    if isee:
        return _isee(args, campaign, store, where, worst_dir)
    from contextlib import ExitStack

    from boatland.cli.common import compile_notice

    from tqdm import tqdm

    with ExitStack() as stack:
        bar = []

        resumed = []

        def progress(done, total):
            if not bar:        # the first call: the store is open (not another campaign's): say what runs
                print(f"campaign {campaign.name}: {len(campaign.cases)} cases × {campaign.seeds} seeds = "
                      f"{campaign.n_trials} trials of {longest.simulation.duration:g} s on {where} → {store}",
                      file=sys.stderr)
                resumed.append(done)
                if done:
                    print(f"resuming: {done} of {total} trials already in the store", file=sys.stderr)
                if done < total:
                    compile_notice()
                bar.append(stack.enter_context(tqdm(total=total, unit="trial", file=sys.stderr, disable=None,
                                                    dynamic_ncols=True)))
            bar[0].n = done
            bar[0].refresh()

        result = run_campaign(campaign, store, loaders=(load, resolve_database),
                              executor="dask" if args.scheduler else "local", workers=args.workers,
                              scheduler=args.scheduler, progress=progress, background=background)
    table = result.table()
    failed = failures(campaign, table)
    n_failed = sum(len(v) for v in failed.values())
    for case, rows in sorted(failed.items()):
        label = campaign.cases[case].label() or "base"
        print(f"  case {case} ({label}): {len(rows)} of {campaign.seeds} trials failed: "
              + "; ".join(f"trial {t}: {why}" for t, why in rows[:3]) + (" …" if len(rows) > 3 else ""),
              file=sys.stderr)
    from boatland.campaign.report import store_decision

    dec = store_decision(store, target=args.target, width=args.width)
    files = write_report(store, args.report, incident=dec.incident, target=args.target, width=args.width) \
        if args.report else []
    done_before = resumed[0] if resumed else 0
    if args.json:
        from boatland.cli.common import print_json

        print_json({"store": str(store), "campaign": campaign.name, "trials": len(table),
                    "run_now": len(table) - done_before, "resumed_from": done_before, "failed": n_failed,
                    "failures": {str(c): [{"trial": t, "reason": why} for t, why in rows] for c, rows in failed.items()},
                    "decision": dec.as_dict(), "report_files": [str(f) for f in files]})
    else:
        print(dec.text())
        print(f"wrote {store}: {len(table)} trials"
              + (f" ({len(table) - done_before} run now, {done_before} from before)" if done_before else "")
              + (f", {n_failed} failed (left out of every probability)" if n_failed else "")
              + ("" if args.report else f"; 'boatland report {store} -o DIR' for tables and figures"))
        if args.report:
            print(f"wrote {len(files)} report files to {args.report}")
    if n_failed and not args.allow_failures:
        print(f"boatland: error: {n_failed} of {len(table)} trials failed (see above; --allow-failures to accept "
              "them)", file=sys.stderr)
        return 1
    return 0


def _isee(args, campaign, store, where, worst_dir) -> int:
    """``boatland campaign`` with method isee: the runs, their estimates, the limiting Hs, the heaviest samples."""
    from contextlib import ExitStack

    from tqdm import tqdm

    import numpy as np

    from boatland.campaign.isee import run_isee
    from boatland.freqdomain.statistics import ACCESS_DURATION, DEFAULT_STATISTICS, one_in, risk_in_words
    from boatland.campaign.report import write_report
    from boatland.cli.common import compile_notice
    from boatland.checks.files import load, resolve_database

    s = campaign.isee
    with ExitStack() as stack:
        bar = []

        def progress(done, total):
            if not bar:
                print(f"campaign {campaign.name} (isee): {len(campaign.cases)} cases, incident {s.incident!r}, target "
                      f"CoV {s.target_cov:g}" + (f", limiting Hs at P = {s.accept:g} ({one_in(s.accept)})" if s.accept is not None else "")
                      + f" on {where} → {store}", file=sys.stderr)
                compile_notice()
                bar.append(stack.enter_context(tqdm(total=total, unit="sample", file=sys.stderr, disable=None,
                                                    dynamic_ncols=True)))
            bar[0].total = max(total, bar[0].total or 0)
            bar[0].n = done
            bar[0].refresh()

        result = run_isee(campaign, store, loaders=(load, resolve_database),
                          executor="dask" if args.scheduler else "local", workers=args.workers,
                          scheduler=args.scheduler, progress=progress)
    from boatland.campaign.report import read_store

    data = read_store(store)
    runs = data["stats"]
    n_failed = int(runs["failed"].sum())
    inc = s.incident
    if args.json:
        from boatland.cli.common import print_json

        def rows(table):
            return [{k: (v.decode() if isinstance(v, bytes) else v.item() if hasattr(v, "item") else v)
                     for k, v in zip(table.dtype.names, r)} for r in table]

        if worst_dir is not None:
            _save_worst(campaign, data["trials"], worst_dir, args.save_worst, inc, quiet=True)
        files = write_report(store, args.report) if args.report else []
        print_json({"store": str(store), "campaign": campaign.name, "method": "isee", "incident": inc,
                    "samples": len(result.rows), "failed": n_failed, "runs": rows(runs),
                    "limits": rows(data["isee_limits"]) if "isee_limits" in data else [],
                    "report_files": [str(f) for f in files]})
        return 1 if n_failed and not args.allow_failures else 0
    stat = DEFAULT_STATISTICS
    onset = "first slip" if inc == "first slip" else "first incident (slip, contact loss or roll)"
    print(f"wrote {store}: {len(result.rows)} samples in {len(runs)} runs"
          + (f", {n_failed} failed (left out)" if n_failed else ""))
    for r in runs:
        label = r["label"].decode() or "base"
        print(f"  case {r['case']} ({label}) Hs {r['hs']:.4g} m: P({inc}) = {r[f'{inc}: P']:.3g} "
              f"[{r[f'{inc}: P lo']:.3g}, {r[f'{inc}: P hi']:.3g}] (CoV {r[f'{inc}: CoV']:.2g}, {r['samples']} samples); "
              f"P(first slip): linear {r['linear first slip: P']:.3g}, screening ({stat}) {r['screening ' + stat]:.3g}")
    if "isee_limits" in data:
        for L in data["isee_limits"]:
            c = int(L["case"])
            mine = runs[runs["case"] == c]
            levels = mine["hs"] if mine.size else np.array([np.nan])
            if np.isfinite(L["limiting Hs"]):
                found = (f"limiting Hs {L['limiting Hs']:.4g} m {_limit_interval(L, levels)} for P({inc}) = "
                         f"{L['accept']:g}")
            else:                                  # no level saw the incident: say how far it looked
                top = mine[np.argmax(mine["hs"])] if mine.size else None
                found = (f"no limiting Hs for P({inc}) = {L['accept']:g}: no {inc} in {int(mine['samples'].sum())} "
                         f"samples" + (f" up to Hs {top['hs']:.4g} m, where P(first slip) = "
                                       f"{top['linear first slip: P']:.2g} (the importance sampling of the first "
                                       "slip gains nothing where it is near-certain: a Monte Carlo campaign there "
                                       "bounds it)" if top is not None else ""))
            lin, scr = L["linear limiting Hs"], L["screening " + stat + " Hs"]
            print(f"  case {c} ({L['label'].decode() or 'base'}): {found}; onset limits: the linear model's {onset} "
                  + (f"{lin:.4g} m" if np.isfinite(lin) else
                     f"not found ({_no_limit_why(levels)})")
                  + f", the screening's first slip ({stat}) "
                  + (f"{scr:.4g} m" if np.isfinite(scr) else "not found"))
        print(f"  accepted: {risk_in_words(float(data['isee_limits'][0]['accept']), campaign.access or ACCESS_DURATION)}")
    if worst_dir is not None:
        _save_worst(campaign, data["trials"], worst_dir, args.save_worst, inc)
    if args.report:
        files = write_report(store, args.report)
        print(f"wrote {len(files)} report files to {args.report}")
    if n_failed and not args.allow_failures:
        print(f"boatland: error: {n_failed} samples failed (see the store; --allow-failures to accept them)",
              file=sys.stderr)
        return 1
    return 0


def _save_worst(campaign, table, folder: Path, n: int, incident: str, quiet: bool = False) -> None:
    """The ``n`` heaviest samples run again, exactly, each with its run log ``sample_<trial>.mcap``."""
    from boatland.campaign.isee import rerun_sample, worst_samples
    from boatland.record.mcap_log import McapLog
    from boatland.checks.files import load, resolve_database

    folder.mkdir(exist_ok=True)
    for trial in worst_samples(table, incident, n):
        row = table[table["trial"] == trial][0]
        path = folder / f"sample_{trial}.mcap"
        log = McapLog(path)
        try:
            rerun_sample(campaign, row, (load, resolve_database), sinks=[log])
        finally:
            log.close()
        w = float(__import__("math").exp(row["isee_log_pbar"]) / row["isee_n"])
        if not quiet:
            print(f"wrote {path} (weight {w:.3g}; {row['events'].decode() or 'no events in the access'}; "
                  f"'boatland replay {path}' for Rerun)")


def _no_limit_why(levels) -> str:
    """Why a limit fit found nothing (:func:`boatland.campaign.isee.limit_fit` looks within ×3 of the levels)."""
    import numpy as np

    return (f"its P does not cross the target between Hs {np.nanmin(levels) / 3:.3g} and {np.nanmax(levels) * 3:.3g} m, "
            "a third of the lowest level searched and three times the highest")


def _limit_interval(L, levels) -> str:
    """The limiting Hs's 95 % interval in words where an end was not found within ×3 of the levels searched."""
    import numpy as np

    lo, hi = L["limiting Hs lo"], L["limiting Hs hi"]
    left = f"{lo:.4g}" if np.isfinite(lo) else f"< {np.nanmin(levels) / 3:.3g}"
    right = f"{hi:.4g}" if np.isfinite(hi) else f"> {np.nanmax(levels) * 3:.3g}"
    note = "" if np.isfinite(lo) and np.isfinite(hi) else (
        " (an end of the interval lies beyond ×3 of the levels searched: more samples or levels narrow it)")
    return f"[{left}, {right}]{note}"
