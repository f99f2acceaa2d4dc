"""``boatland run``: one landing trial from a scenario file, with its run log and optional Rerun stream."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from boatland.errors import BoatlandInputError

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    run = sub.add_parser(
        "run", help="run one landing trial from a scenario file (default: the built-in CTV trial)",
        description="Run one landing trial: the vessel pushing its bow fender against the boat landing in "
                    "the scenario's sea, RK4 Cummins integration with stick–slip fender contact. Prints a "
                    "summary: slip events, time to first slip, slip distance, normal forces, motions, "
                    "incidents. Without a file: scenarios/ctv_landing.toml (24 m CTV, JONSWAP Hs 1.5 m, "
                    "80 kN).")
    run.add_argument("scenario", nargs="?", type=Path, help="scenario file (TOML); see 'boatland scenario schema'")
    run.add_argument("--json", action="store_true", help="print the summary as JSON")
    run.add_argument("-o", "--output", type=Path, help="write the time series, events and summary (HDF5)")
    run.add_argument("--duration", type=float, help="override simulation.duration [s]")
    run.add_argument("--seed", type=int, help="override simulation.seed")
    run.add_argument("--log", type=Path, metavar="MCAP",
                     help="run log to write (MCAP, written while the trial runs; opens in Foxglove and in Rerun: "
                          "'boatland replay'). Default: <scenario name>.mcap next to -o FILE if given, else in "
                          "the current directory")
    run.add_argument("--no-log", action="store_true", help="write no run log")
    run.add_argument("--rerun", metavar="TARGET",
                     help="also stream the run to Rerun: 'save=PATH.rrd' (a file), 'serve' (viewers connect to "
                          "the printed URL), 'connect[=URL]' (a viewer already listening; default "
                          "rerun+http://127.0.0.1:9876/proxy), 'spawn' (start a viewer; needs a display). "
                          "Never waits for an absent viewer: that is an error before the run")
    run.set_defaults(func=cmd)


def cmd(args) -> int:
    import warnings

    from boatland.scenario_check import default_scenario_path, load_checked
    from boatland.trial.simulate import BlowUpError, simulate

    path = args.scenario or default_scenario_path()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scenario, db, _ = load_checked(path)
        changes = {}
        if args.duration is not None:
            changes["simulation.duration"] = args.duration
        if args.seed is not None:
            changes["simulation.seed"] = args.seed
        if changes:
            scenario = scenario.replace(changes)
        if not args.json:
            print(f"running {scenario.name}: {scenario.simulation.duration:g} s at dt = {scenario.time_step(db):g} s "
                  f"({scenario.n_steps(db)} steps), {db.name}, radiation {scenario.radiation.method}", file=sys.stderr)
        sinks, log_path, live = _recording_sinks(args, scenario)
        try:
            result = _simulate_with_bar(simulate, scenario, db, show=not args.json, sinks=sinks)
        except BlowUpError as exc:
            print(f"boatland: error: {path}: {exc}", file=sys.stderr)
            if log_path is not None:
                print(f"wrote {log_path} (up to the blow-up)", file=sys.stderr)
            return 3
        finally:
            for sink in sinks:      # an interrupted run still leaves a valid log of what was done
                sink.close()
    for w in caught:
        if not args.json:
            print(f"warning: {w.message}", file=sys.stderr)
    if args.output:
        result.to_hdf5(args.output)
    if args.json:
        print(json.dumps(result.summary(), indent=2, default=float))
    else:
        print(result.summary_text())
        if args.output:
            print(f"wrote {args.output}")
        if log_path is not None:
            print(f"wrote {log_path} (run log; 'boatland replay {log_path}' for Rerun, 'boatland plot' for a figure)")
    if live is not None and live.kind == "save":
        print(f"wrote {live.where} (open it with 'rerun {live.where}')", file=sys.stderr if args.json else sys.stdout)
    if live is not None and live.kind == "serve":
        from boatland.record.rerun_log import serve_until_interrupted

        serve_until_interrupted(live.where)
    return 0


def _recording_sinks(args, scenario):
    """The run log (MCAP) and the optional Rerun stream of ``boatland run``: (sinks, log path, Rerun sink)."""
    import uuid

    from boatland.record.mcap_log import McapLog
    from boatland.record.rerun_log import RerunLog

    run_id = str(uuid.uuid4())
    live = RerunLog(args.rerun, recording_id=run_id, quiet=args.json) if args.rerun else None  # checked now
    sinks, log_path = [], None
    if not args.no_log:
        if args.log is not None:
            log_path = args.log
        elif args.output is not None:
            log_path = args.output.with_suffix(".mcap")
        else:
            log_path = Path(f"{scenario.name}.mcap")
        if not log_path.resolve().parent.is_dir():
            raise BoatlandInputError(f"--log {log_path}: the directory {log_path.parent} does not exist")
        sinks.append(McapLog(log_path, run_id=run_id))
    if live is not None:
        sinks.append(live)
    return sinks, log_path, live


def _simulate_with_bar(simulate, scenario, db, *, show: bool, sinks=()):
    """Run one trial with a progress bar on stderr (simulated seconds; hidden when stderr is not a
    terminal or ``show`` is False), feeding ``sinks`` (run log, Rerun) as it runs."""
    if not show:
        return simulate(scenario, db, sinks=sinks)
    from tqdm import tqdm

    dt = scenario.time_step(db)
    with tqdm(total=round(scenario.n_steps(db) * dt, 2), unit="s", unit_scale=False, file=sys.stderr,
              disable=None, leave=False, desc="simulated", dynamic_ncols=True,
              bar_format="{desc} {n:.1f}/{total:.1f} s |{bar}| {elapsed}<{remaining}") as bar:
        def progress(done, total):
            bar.n = round(done * dt, 2)
            bar.refresh()

        return simulate(scenario, db, progress=progress, sinks=sinks)
