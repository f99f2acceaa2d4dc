"""``boatland run``: one landing trial from a scenario file, with its run log and optional Rerun stream."""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

from boatland.cli.common import set_option, shipped_or_path
from boatland.cli.guard import accept_arg, integer, positive, seed

__all__ = ["add_parser", "cmd"]


def add_parser(sub) -> None:
    run = sub.add_parser(
        "run", help="run one landing trial from a scenario file (default: the built-in CTV trial)",
        description="Run one landing trial: the vessel pushing its bow fender against the boat landing in "
                    "the scenario's sea, RK4 Cummins integration with stick–slip fender contact. Prints the "
                    "verdict first — the sea state, push and μ it judged, and whether the fender held or slipped "
                    "(when, how far) against the scenario's incident thresholds — then slip events, slip "
                    "distance, forces, motions, incidents and the events after the settling (contacts that "
                    "change together on one line) — and, under the verdict, the odds of this sea: the "
                    "frequency-domain screening's probability per 30-min access of a slip onset (which bounds "
                    "every slip and slide incident) and of roll beyond each limit, against the accepted risk "
                    "(--accept). One trial's luck is not the sea's risk. Without a file: "
                    "scenarios/ctv_landing.toml (the 27 m CTV ctv27 pushing 150 kN in JONSWAP Hs 0.4 m, Tp 7 s, "
                    "head seas).")
    run.add_argument("scenario", nargs="?", type=shipped_or_path("scenario"),
                     help="scenario file (TOML; see 'boatland scenario schema') or the name of a shipped one, e.g. "
                          "ctv24_landing (default: ctv_landing)")
    set_option(run)
    run.add_argument("--json", action="store_true",
                     help="print the verdict, inputs, summary and events as JSON (values rounded to the model's "
                          "resolution)")
    run.add_argument("--events", choices=("waves", "all", "none"), default="waves",
                     help="events to list: after the settling (default), all (with the thrust ramp's settling), none")
    run.add_argument("-o", "--output", type=Path,
                     help="write the time series, events and summary (netCDF-4/HDF5: xarray.open_dataset opens it "
                          "with named dimensions and units)")
    length = run.add_mutually_exclusive_group()
    length.add_argument("--duration", type=positive("s"),
                        help="the whole trial [s], settling and wave ramp included (overrides simulation.duration)")
    length.add_argument("--access", type=positive("s"), metavar="S",
                        help="the access [s]: how long the full sea lasts after the settling and the wave ramp — the "
                             "time a campaign's incidents count over (its access); the trial runs that much longer")
    run.add_argument("--accept", type=accept_arg, default="best", metavar="P",
                     help="accepted probability of an incident per 30-min access, in (0, 1), or a preset of Grøtting "
                          "(2015) Table 2.1: best (1.19e-3, default), conservative (2e-5), non-conservative (2.681e-2)")
    run.add_argument("--seed", type=seed, help="override simulation.seed (0 … 2**63 − 1). The sea is fixed by the seed, "
                                               "the spectrum and the component keys ([sea] n_components, "
                                               "repeat_period = 600 s, band_tail): a run up to repeat_period long "
                                               "is the start of the same sea whatever --duration")
    logs = run.add_mutually_exclusive_group()
    logs.add_argument("--log", type=Path, metavar="MCAP",
                     help="run log to write (MCAP, written while the trial runs; opens in Foxglove and in Rerun: "
                          "'boatland replay'). Default: <scenario name>.mcap next to -o FILE if given, else in "
                          "the current directory")
    logs.add_argument("--no-log", action="store_true", help="write no run log")
    run.add_argument("--rerun", metavar="TARGET",
                     help="also stream the run to Rerun: 'save=PATH.rrd' (a file), 'serve' (viewers connect to "
                          "the printed URL), 'connect[=URL]' (a viewer already listening; default "
                          "rerun+http://127.0.0.1:9876/proxy), 'spawn' (start a viewer; needs a display). "
                          "Never waits for an absent viewer: that is an error before the run")
    run.add_argument("--bind", metavar="ADDR", default="127.0.0.1",
                     help="address the --rerun serve server, or the viewer --rerun spawn starts, listens on (default "
                          "127.0.0.1: this machine only; 0.0.0.0 opens it to the network, without authentication)")
    run.add_argument("--port", type=integer(1, 65535), default=9876,
                     help="port of --rerun serve or of the viewer --rerun spawn starts (default 9876)")
    run.add_argument("--progress-file", type=Path, metavar="FILE",
                     help="keep the kernel's step counter in FILE while the trial runs (for scripts and tests)")
    run.set_defaults(func=cmd)


def cmd(args) -> int:
    from boatland.cli.common import check_fits_in_memory, compile_notice, load_guarded, settings_changes
    from boatland.trial.simulate import BlowUpError, simulate

    path = args.scenario
    if args.rerun:
        from boatland.record.rerun_log import parse_target

        parse_target(args.rerun, bind=args.bind, port=args.port)       # a bad spec fails first
    changes = {k: v for k, v in (("simulation.duration", args.duration), ("simulation.seed", args.seed))
               if v is not None}
    changes, flags = settings_changes(args, changes, {"simulation.duration": "--duration", "simulation.seed": "--seed"})
    derived = None
    if args.access is not None:
        from boatland.trial.simulate import exposure_start

        derived = lambda sc: ({"simulation.duration": exposure_start(sc) + args.access},  # noqa: E731
                              {"simulation.duration": f"--access {args.access:g}: a trial of"})
    scenario, db, warns, setup = load_guarded(path, lambda sc: _outputs(args, sc), changes=changes, flags=flags,
                                              derived=derived)
    check_fits_in_memory(setup, flag="--duration" if args.duration is not None else "--access" if args.access is not None
                         else f"{scenario.source}: simulation.duration")
    sinks, log_path, live = _recording_sinks(args, scenario)
    compile_notice()
    if not args.json:
        from boatland.trial.simulate import exposure_start

        T, start = scenario.simulation.duration, exposure_start(scenario)
        parts = (f"{start:g} s of settling and wave ramp, then {T - start:g} s of the full sea (the access)"
                 if T > start else f"the waves still ramping in at the end ({start:g} s to the full sea)")
        print(f"running {scenario.name}: {T:g} s — {parts} — at dt = {setup.dt:g} s "
              f"({setup.n_steps} steps), {db.name}, radiation {scenario.radiation.method}", file=sys.stderr)
        for line in setup.environment.lines(scenario):
            print(f"  {line}", file=sys.stderr)
    try:
        result = _simulate_with_bar(simulate, setup, show=not args.json, sinks=sinks,
                                    progress_file=args.progress_file)
    except BlowUpError as exc:
        print(f"boatland: error: {path or scenario.source}: {exc}", file=sys.stderr)
        if log_path is not None:
            print(f"wrote {log_path} (up to the blow-up)", file=sys.stderr)
        return 3
    finally:
        for sink in sinks:      # an interrupted run still leaves a valid log of what was done
            sink.close()
    if not args.json:
        for w in warns:
            print(f"warning: {w}", file=sys.stderr)
    if args.output:
        result.to_hdf5(args.output)
    risk = _sea_risk(scenario, db, setup, args.accept)
    defs, outcome = result.incident_definitions, result.verdict().outcome
    if args.json:
        out = result.report(args.events)
        out["risk"] = ({"available": False, "reason": risk} if isinstance(risk, str)
                       else {"available": True, **risk.as_dict(defs, outcome)})
        print(json.dumps(out, indent=2, default=float, ensure_ascii=False))
    else:
        text = result.summary_text(args.events).split("\n")
        odds = [f"  (no odds for this sea: {risk})"] if isinstance(risk, str) else risk.lines(defs, outcome)
        print("\n".join(text[:1] + odds + text[1:]))
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


def _sea_risk(scenario, db, setup, accept):
    """The screening's odds of this sea (:func:`boatland.freqdomain.risk.sea_risk`), or the reason there are
    none (a string: no spectral sea, no landing)."""
    from boatland.errors import BoatlandInputError
    from boatland.freqdomain.risk import sea_risk

    try:
        return sea_risk(scenario, db, setup=setup, accept=accept)
    except BoatlandInputError as exc:
        return str(exc).split(": ", 1)[-1]


def _log_path(args, scenario) -> Path | None:
    """The run log: --log, else beside -o, else <scenario name>.mcap here; None with --no-log."""
    if args.no_log:
        return None
    if args.log is not None:
        return args.log
    if args.output is not None:
        return args.output.with_suffix(".mcap")
    return Path(f"{scenario.name}.mcap")


def _outputs(args, scenario) -> list:
    from boatland.outputs import Output

    outs = [Output("-o", args.output)]
    log = _log_path(args, scenario)
    if log is not None:
        outs.append(Output("--log" if args.log is not None else "the run log (--log)", log))
    if args.rerun and args.rerun.startswith("save="):
        outs.append(Output("--rerun save=", Path(args.rerun[5:])))
    if args.progress_file is not None:
        outs.append(Output("--progress-file", args.progress_file))
    return outs


def _recording_sinks(args, scenario):
    """The run log (MCAP) and the optional Rerun stream of ``boatland run``: (sinks, log path, Rerun sink)."""
    import uuid

    from boatland.record.mcap_log import McapLog
    from boatland.record.rerun_log import RerunLog

    run_id = str(uuid.uuid4())
    live = RerunLog(args.rerun, recording_id=run_id, quiet=args.json, bind=args.bind, port=args.port) \
        if args.rerun else None  # checked now: an absent viewer or a busy port fails before the run
    sinks, log_path = [], _log_path(args, scenario)
    if log_path is not None:
        sinks.append(McapLog(log_path, run_id=run_id))
    if live is not None:
        sinks.append(live)
    return sinks, log_path, live


def _simulate_with_bar(simulate, setup, *, show: bool, sinks=(), progress_file: Path | None = None):
    """Run one trial with a progress bar on stderr (simulated seconds; hidden when stderr is not a
    terminal or ``show`` is False), feeding ``sinks`` (run log, Rerun) as it runs. ``progress_file``:
    also keep the kernel's step counter in this file (one number, rewritten in place as it grows)."""
    from contextlib import ExitStack

    scenario, db, dt = setup.scenario, setup.db, setup.dt
    with ExitStack() as stack:
        report = []
        if progress_file is not None:
            fd = os.open(progress_file, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
            stack.callback(os.close, fd)
            report.append(lambda done, total: os.pwrite(fd, f"{done:>20d}\n".encode(), 0))
        if show:
            from tqdm import tqdm

            bar = stack.enter_context(tqdm(
                total=round(setup.n_steps * dt, 2), unit="s", unit_scale=False, file=sys.stderr,
                disable=None, leave=False, desc="simulated", dynamic_ncols=True,
                bar_format="{desc} {n:.1f}/{total:.1f} s |{bar}| {elapsed}<{remaining}"))

            shown = [0.0]

            def to_bar(done, total):
                if time.monotonic() - shown[0] >= 0.1:
                    bar.n = round(done * dt, 2)
                    bar.refresh()
                    shown[0] = time.monotonic()
            report.append(to_bar)
        if not report:
            return simulate(scenario, db, sinks=sinks, setup=setup)

        def progress(done, total):
            for r in report:
                r(done, total)

        return simulate(scenario, db, progress=progress, sinks=sinks, setup=setup,
                        progress_every=0.0 if progress_file is not None else 0.1)
