"""The ``boatland`` command (also ``python -m boatland``).

User mistakes (:class:`boatland.errors.BoatlandInputError`) print one line and exit with status 2;
anything else is a bug and keeps its traceback.
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import sys
from pathlib import Path

from boatland import __version__
from boatland.errors import BoatlandInputError

__all__ = ["main"]

DEFAULT_VESSEL = "ctv24"


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    parser = _parser()
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING,
                        format="%(levelname)s: %(message)s")
    if not hasattr(args, "func"):
        parser.print_help()
        return 0
    try:
        return int(args.func(args) or 0)
    except BoatlandInputError as exc:
        print(f"boatland: error: {exc}", file=sys.stderr)
        return exc.exit_status
    except KeyboardInterrupt:
        print("boatland: interrupted", file=sys.stderr)
        return 130


# ---------------------------------------------------------------------------------------- parser
def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="boatland",
        description="Crew transfer vessel on a boat landing: will the fender hold, and if it slips, "
                    "when and how far?",
        epilog="Start with 'boatland run' (the default CTV landing trial), or 'boatland <command> --help'.",
    )
    p.add_argument("--version", action="version", version=f"boatland {__version__}")
    p.add_argument("-v", "--verbose", action="store_true", help="say more about what is being done")
    sub = p.add_subparsers(title="commands", metavar="COMMAND")

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
    run.set_defaults(func=_cmd_run)

    rpl = sub.add_parser(
        "replay", help="replay a run log (MCAP) in the Rerun viewer: 3D scene, plots, events",
        description="Read a run log written by 'boatland run' (a truncated log of a killed run is recovered "
                    "up to its last complete second, and what is lost is said) and send it to Rerun with the "
                    "scene and layout of the live stream. Without an option: --save <log>.rrd.")
    rpl.add_argument("log", type=Path, help="run log (.mcap)")
    how = rpl.add_mutually_exclusive_group()
    how.add_argument("--save", type=Path, metavar="RRD", help="write a Rerun file (open it with 'rerun FILE.rrd')")
    how.add_argument("--serve", action="store_true", help="serve to Rerun viewers (prints the URL to open)")
    how.add_argument("--spawn", action="store_true", help="start a Rerun viewer (needs a display)")
    how.add_argument("--connect", metavar="URL", nargs="?", const="", help="send to a Rerun viewer already listening")
    rpl.set_defaults(func=_cmd_replay)

    plo = sub.add_parser(
        "plot", help="figure of a run log: motions, fender forces vs available friction, slip distance",
        description="Plot the main time series of a run log (MCAP) for a report: heave/roll/pitch, fender "
                    "normal force with the friction needed to stick and the friction available, slip distance "
                    "from the landing position, with slip starts and incidents marked.")
    plo.add_argument("log", type=Path, help="run log (.mcap)")
    plo.add_argument("-o", "--output", type=Path, help="figure file (.png, .pdf, .svg; default <log>.png)")
    plo.set_defaults(func=_cmd_plot)

    camp = sub.add_parser(
        "campaign", help="Monte Carlo slip-probability campaign: many trials over a sweep, into a resumable store",
        description="Run every trial of a campaign file (a base scenario, axes to sweep, N seeds per case) on "
                    "local worker processes or a Dask cluster. Results go to an HDF5 store as they arrive; "
                    "running the same command again resumes where it stopped (no trial lost or run twice). "
                    "Example: boatland campaign scenarios/campaigns/demo.toml")
    camp.add_argument("campaign", type=Path, help="campaign file (TOML); see scenarios/campaigns/")
    camp.add_argument("-o", "--output", type=Path, help="store (HDF5; default: <campaign name>.h5 here)")
    camp.add_argument("--workers", type=int, help="local worker processes (default: all cores)")
    camp.add_argument("--scheduler", metavar="URL", help="run on a Dask scheduler (tcp://host:port) instead")
    camp.add_argument("--report", type=Path, metavar="DIR", help="also write the report into DIR at the end")
    camp.set_defaults(func=_cmd_campaign)

    rep = sub.add_parser(
        "report", help="tables and figures of a finished campaign store",
        description="Write per-case tables (CSV and Markdown: P(incident) with Clopper–Pearson intervals, mean "
                    "time to the incident with χ² intervals), the limiting Hs table and figures (P vs Hs, "
                    "limiting Hs polar, time-to-incident distributions).")
    rep.add_argument("store", type=Path, help="campaign store (HDF5) written by 'boatland campaign'")
    rep.add_argument("-o", "--output", type=Path, default=Path("report"), help="folder (default: ./report)")
    rep.add_argument("--incident", help="incident definition for limiting Hs and figures (default: the "
                                        "first slip-distance definition)")
    rep.add_argument("--target", type=float, default=0.1,
                     help="accepted probability of the incident within the access (default 0.1)")
    rep.set_defaults(func=_cmd_report)

    scen = sub.add_parser("scenario", help="scenario files: validate, JSON Schema",
                          description="Scenario files (TOML): check one without running it, or print the JSON "
                                      "Schema for editors.")
    ssub = scen.add_subparsers(title="scenario commands", metavar="SCENARIO_COMMAND")
    scen.set_defaults(func=lambda a: scen.print_help())
    chk = ssub.add_parser("check", help="validate a scenario file and its physics against the database")
    chk.add_argument("file", type=Path)
    chk.set_defaults(func=_cmd_scenario_check)
    sch = ssub.add_parser("schema", help="print the JSON Schema of scenario files")
    sch.set_defaults(func=lambda a: print(__import__("boatland.scenario_check", fromlist=["x"]).schema_text()))

    hydro = sub.add_parser("hydro", help="hydrodynamic databases: import BEM output, summarise, build",
                           description="Hydrodynamic databases (BEMIO HDF5): import, summarise, build.")
    hsub = hydro.add_subparsers(title="hydro commands", metavar="HYDRO_COMMAND")
    hydro.set_defaults(func=lambda a: hydro.print_help())

    from boatland.hydro import FORMATS

    imp = hsub.add_parser(
        "import", help="convert WAMIT/NEMOH/AQWA/Capytaine/BEMIO output to a boatland database",
        description="Read BEM output, convert units and phase convention to boatland's, and write a "
                    "database (BEMIO HDF5). Accepted inputs:\n  "
                    + "\n  ".join(f"{k:10s} {v}" for k, v in FORMATS.items()),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    imp.add_argument("path", type=Path, help="BEM output file or folder")
    imp.add_argument("-o", "--output", type=Path, required=True, help="database to write (.h5)")
    imp.add_argument("--format", choices=sorted(FORMATS), help="force a reader instead of detecting it")
    imp.add_argument("--rho", type=float, help="water density [kg/m³] for formats that do not store it "
                                               "(WAMIT; default 1025)")
    imp.add_argument("--g", type=float, help="gravity [m/s²] for formats that do not store it")
    imp.add_argument("--name", help="vessel name to store (default: from the file)")
    imp.set_defaults(func=_cmd_import)

    info = hsub.add_parser("info", help="summarise a database: band, directions, natural periods, warnings",
                           description="Summarise a hydrodynamic database (or any BEM output boatland "
                                       "reads): frequency range, directions, heave/roll/pitch natural "
                                       "periods, and warnings (negative damping, missing A∞, "
                                       "irregular-frequency spikes, dropped frequencies).")
    info.add_argument("database", nargs="?", default=DEFAULT_VESSEL,
                      help=f"database file, BEM output, or a built-in vessel name (default: {DEFAULT_VESSEL})")
    info.add_argument("--json", action="store_true", help="print the summary as JSON")
    info.set_defaults(func=_cmd_info)

    build = hsub.add_parser("build", help="compute a catamaran database with Capytaine from a vessel file",
                            description="Build a hydrodynamic database for a parametric catamaran (two "
                                        "Wigley-type demihulls) with Capytaine: radiation and diffraction "
                                        "over the vessel file's frequencies and directions, A∞ and A₀, "
                                        "hydrostatics, mass matrix. Examples: scenarios/vessels/*.toml.")
    build.add_argument("vessel", type=Path, help="vessel file (TOML)")
    build.add_argument("-o", "--output", type=Path, help="database to write (default: <vessel>.h5 beside "
                                                         "the current directory)")
    build.add_argument("--no-progress", action="store_true", help="no progress bar")
    build.set_defaults(func=_cmd_build)

    lst = hsub.add_parser("list", help="list the built-in vessel databases")
    lst.set_defaults(func=_cmd_list)

    irf = sub.add_parser(
        "irf", help="radiation impulse-response functions and state-space fit of a database",
        description="Compute the radiation IRFs K(t) = (2/π)∫B(ω)cos(ωt)dω of a database, check them "
                    "(B and A reconstructed from K, truncation at T_K, Ogilvie's A∞), fit a stable "
                    "state-space model per DOF pair, print the figures and store everything in the "
                    "database file (BEMIO impulse_response_fun / state_space groups).")
    irf.add_argument("database", nargs="?", default=DEFAULT_VESSEL,
                     help=f"database file or built-in vessel name (default: {DEFAULT_VESSEL})")
    irf.add_argument("--t-max", type=float, default=60.0, help="memory length T_K [s] (default 60)")
    irf.add_argument("--dt", type=float, help="time step of K [s] (default min(0.05, π/(3 ω_max)))")
    irf.add_argument("--tail", choices=("auto", "linear", "none", "asymptotic"), default="auto",
                     help="B(ω) above the band: straight to zero over 20%% of ω_max, stop, extrapolate "
                          "∝ ω^-n, or auto (default): linear when the damping has decayed at the top of "
                          "the band, else ω^-n with a note")
    irf.add_argument("--taper", choices=("none", "cosine"), default="none", help="time window on K")
    irf.add_argument("--clean", choices=("clip", "cut", "none"), default="clip",
                     help="negative damping: clip to zero (default), cut the band, or keep")
    irf.add_argument("--band", type=float, nargs=2, metavar=("LO", "HI"),
                     help="frequency band [rad/s] of the round-trip check (default: the whole band)")
    irf.add_argument("--target-r2", type=float,
                     help="state-space fit target R² (default 0.99999: boatland.model.radiation.TARGET_R2)")
    irf.add_argument("--max-order", type=int,
                     help="largest state-space order per pair (default 40: boatland.model.radiation.MAX_ORDER)")
    irf.add_argument("--no-fit", action="store_true", help="skip the state-space fit")
    irf.add_argument("--plot", type=Path, metavar="PNG", help="write a figure of K(t), B and A")
    irf.add_argument("-o", "--output", type=Path,
                     help="write the database with IRFs to this file instead of updating it in place "
                          "(built-in databases are never modified)")
    irf.add_argument("--no-store", action="store_true", help="do not write anything")
    irf.add_argument("--json", action="store_true", help="print the figures as JSON")
    irf.set_defaults(func=_cmd_irf)
    _add_freqdomain_parsers(sub)
    return p


def _add_freqdomain_parsers(sub) -> None:
    """``rao``, ``screen`` and ``operability`` (frequency domain, issue 8)."""
    def common(cmd, scenario_optional=True):
        if scenario_optional:
            cmd.add_argument("scenario", nargs="?", type=Path,
                             help="scenario file (TOML; default: scenarios/ctv_landing.toml)")
        else:
            cmd.add_argument("scenario", type=Path, help="scenario file (TOML)")

    def screening_options(cmd):
        cmd.add_argument("--accept", default="best", metavar="P",
                         help="accepted probability of an incident per access, in (0, 1), or a preset of seed 002 "
                              "Table 2.1: best (0.00119), conservative (0.00002), non-conservative (0.02681); "
                              "default best")
        cmd.add_argument("--statistics", choices=("rayleigh", "rice", "vanmarcke"), default="rayleigh",
                         help="Rayleigh peaks, one per Tp (seed 002), or Rice up-crossing rates (optionally with "
                              "Vanmarcke's clumping correction); default rayleigh")
        cmd.add_argument("--method", choices=("improved", "wu"), default="improved",
                         help="hinge model: improved = thrust follows the vessel, fender spring normal (seed 002 "
                              "§3.4); wu = rigid hinge, thrust only a static normal force (§3.2.1); default improved")
        cmd.add_argument("--mu", type=float, help="friction coefficient μ (default fender.mu_s)")
        cmd.add_argument("--thrust", type=float, help="bollard push F_b [N] (default thrust.force)")
        cmd.add_argument("--roll-limit", type=float, metavar="DEG",
                         help="roll limit θ_max [deg] (default the largest incidents.roll_limit_deg, else 10)")
        cmd.add_argument("--access", type=float, default=1800.0, metavar="S",
                         help="duration of one access t_acc [s] (default 1800)")
        cmd.add_argument("--json", action="store_true", help="print the results as JSON")

    rao = sub.add_parser(
        "rao", help="RAOs of the free and the fender-hinged vessel, hinge-force transfer functions",
        description="Free RAO (seed 000 eq. 3.31) and the RAO of the vessel hinged at its fender point(s) "
                    "(seed 002 eq. 3.1–3.12, preloaded by the scenario's thrust), the hinge force on the vessel "
                    "(normal, vertical, horizontal, all contacts) and the motion of the free vessel's fender point, "
                    "per unit wave amplitude, in the scenario's relative wave direction.")
    common(rao)
    rao.add_argument("--direction", type=float, metavar="DEG",
                     help="relative wave direction [deg] (180 = head seas; default the scenario's sea, else 180)")
    rao.add_argument("--periods", type=float, nargs="+", metavar="T",
                     default=[3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0, 12.0, 15.0, 20.0],
                     help="wave periods of the table [s]")
    rao.add_argument("-o", "--output", type=Path, metavar="PNG", help="write a figure")
    rao.add_argument("--json", action="store_true", help="print the table as JSON")
    rao.add_argument("--compare-open-sea", type=Path, metavar="PNG",
                     help="write a figure of the free heave and pitch RAOs in the open sea and beside the "
                          "monopile (its scattered wave, MacCamy–Fuchs) for headings 0, 45, 90, 135, 180°")
    rao.set_defaults(func=_cmd_rao)

    screen = sub.add_parser(
        "screen", help="Wu (2014) slip screening: limiting Hs per (Tp, direction)",
        description="Frequency-domain slip screening (seed 002 §3.2.1, §3.4): slip-margin transfer functions of "
                    "the fender-hinged vessel for downward, upward, left and right slip and roll, their statistics "
                    "in the scenario's spectral shape, and the largest Hs whose incident probability per access is "
                    "accepted, per peak period and relative wave direction. Prints the table; -o writes a polar "
                    "figure.")
    common(screen)
    screening_options(screen)
    screen.add_argument("--tp", type=float, nargs=3, metavar=("MIN", "MAX", "N"), default=[3.0, 18.0, 16],
                        help="peak periods: N from MIN to MAX [s] (default 3 18 16)")
    screen.add_argument("--directions", type=int, default=8, metavar="N",
                        help="N relative directions over 360° (default 8: every 45°)")
    screen.add_argument("-o", "--output", type=Path, metavar="PNG", help="write a polar figure of the limiting Hs")
    screen.set_defaults(func=_cmd_screen)

    op = sub.add_parser(
        "operability", help="availability of access over a wave scatter diagram / hindcast table",
        description="Availability of push-on access (seed 002 §4.1): the share of the time whose sea state "
                    "(Hs, Tp, direction) is below the screening's limiting Hs. SCATTER is a CSV with columns Hs, "
                    "Tp, direction_deg (towards, global) or direction_from_deg, occurrence; see "
                    "scenarios/scatter_north_sea.csv.")
    common(op, scenario_optional=False)
    op.add_argument("scatter", type=Path, help="scatter table (CSV)")
    screening_options(op)
    op.set_defaults(func=_cmd_operability)


# -------------------------------------------------------------------------------------- commands
def _resolve_db(spec: str):
    """A database from a path (any supported format) or a built-in vessel name."""
    from boatland.hydro import read_hydro

    path = Path(spec)
    if path.exists():
        return read_hydro(path)[0]
    from boatland.hydro.builtin import BUILTIN, load_builtin

    if spec in BUILTIN:
        return load_builtin(spec)
    raise BoatlandInputError(f"{spec}: no such file, and not a built-in vessel "
                             f"(built-in: {', '.join(sorted(BUILTIN))})")


def _cmd_import(args) -> int:
    from boatland.hydro import read_hydro, write_bemio

    db, fmt = read_hydro(args.path, fmt=args.format, rho=args.rho, g=args.g)
    if args.name:
        db = db.replace(name=args.name)
    write_bemio(db, args.output)
    print(f"read {args.path} with the {fmt} reader ({db.n_freq} frequencies, {db.n_dir} direction{'s' if db.n_dir != 1 else ''}); "
          f"wrote {args.output}")
    for note in db.provenance.notes:
        print(f"  note: {note}")
    return 0


def _cmd_info(args) -> int:
    from boatland.hydro.info import summary, summary_text

    db = _resolve_db(args.database)
    if args.json:
        print(json.dumps(summary(db), indent=2))
    else:
        print(summary_text(db))
    return 0


def _cmd_build(args) -> int:
    from boatland.hydro.build import build_from_file

    out = args.output or Path(args.vessel.stem + ".h5")
    db = build_from_file(args.vessel, out, progress=not args.no_progress)
    print(f"wrote {out}: {db.n_freq} frequencies, {db.n_dir} directions, "
          f"{db.mesh.n_panels if db.mesh is not None else 0} panels")
    return 0


def _cmd_irf(args) -> int:
    from boatland.hydro.bemio import write_bemio, write_radiation
    from boatland.hydro.irf_report import irf_summary, irf_table, plot_irf
    from boatland.irf.impulse import IRFSettings
    from boatland.model.radiation import MAX_ORDER, TARGET_R2, default_dt, radiation_memory

    db = _resolve_db(args.database)
    dt = args.dt if args.dt is not None else default_dt(db.omega[-1])
    settings = IRFSettings(t_max=args.t_max, dt=dt, tail=args.tail, taper=args.taper, clean=args.clean,
                           check_band=tuple(args.band) if args.band else None)
    memory = radiation_memory(db, settings, fit=not args.no_fit,
                              target_r2=TARGET_R2 if args.target_r2 is None else args.target_r2,
                              max_order=MAX_ORDER if args.max_order is None else args.max_order)
    print(json.dumps(irf_summary(memory), indent=2) if args.json else irf_table(memory))
    if args.plot:
        plot_irf(db, memory, args.plot)
        if not args.json:
            print(f"wrote {args.plot}")
    if args.no_store:
        return 0
    target = args.output
    if target is None:
        if not Path(args.database).exists():
            if not args.json:
                print("built-in database: nothing stored (use -o FILE to write a copy with the IRFs)")
            return 0
        target = Path(args.database)
        from boatland.hydro import detect_format

        if detect_format(target) != "bemio":
            raise BoatlandInputError(f"{target}: not a BEMIO database; import it first "
                                     "('boatland hydro import') or give -o FILE")
    else:
        write_bemio(db, target)
    write_radiation(target, memory, db.rho)
    if not args.json:
        print(f"stored IRFs{'' if args.no_fit else ' and state-space fit'} in {target}")
    return 0


def _cmd_run(args) -> int:
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


def _cmd_replay(args) -> int:
    from boatland.record.replay import replay

    if args.serve:
        target = "serve"
    elif args.spawn:
        target = "spawn"
    elif args.connect is not None:
        target = f"connect={args.connect}" if args.connect else "connect"
    else:
        target = f"save={args.save or args.log.with_suffix('.rrd')}"
    done = replay(args.log, target)
    for note in done.notes:
        print(f"note: {note}", file=sys.stderr)
    log = done.log
    print(f"{args.log}: {len(log.columns)} steps, t = 0 … {log.duration:.2f} s, {len(log.events)} events"
          + ("" if log.complete else " (recovered from a truncated log)"))
    if done.kind == "save":
        print(f"wrote {done.where} (open it with 'rerun {done.where}')")
    elif done.kind == "serve":
        from boatland.record.rerun_log import serve_until_interrupted

        serve_until_interrupted(done.where)
    return 0


def _cmd_plot(args) -> int:
    from boatland.record.plot import plot_run
    from boatland.record.reader import read_run_log

    log = read_run_log(args.log)
    for note in log.notes:
        print(f"note: {note}", file=sys.stderr)
    out = plot_run(log, args.output or args.log.with_suffix(".png"))
    print(f"wrote {out}")
    return 0


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


def _cmd_campaign(args) -> int:
    from boatland.campaign import load_campaign, run_campaign
    from boatland.campaign.report import write_report
    from boatland.scenario_check import load, resolve_database

    if args.workers is not None and args.workers < 1:
        raise BoatlandInputError(f"--workers must be ≥ 1, got {args.workers}")
    campaign = load_campaign(args.campaign, load_scenario=load)
    store = args.output or Path(f"{campaign.name}.h5")
    where = f"Dask scheduler {args.scheduler}" if args.scheduler else \
        f"{args.workers or os.cpu_count()} local worker process(es)"
    print(f"campaign {campaign.name}: {len(campaign.cases)} cases × {campaign.seeds} seeds = {campaign.n_trials} "
          f"trials of {campaign.base.simulation.duration:g} s on {where} → {store}", file=sys.stderr)
    from tqdm import tqdm

    with tqdm(total=campaign.n_trials, unit="trial", file=sys.stderr, disable=None, dynamic_ncols=True) as bar:
        def progress(done, total):
            bar.n = done
            bar.refresh()

        result = run_campaign(campaign, store, loaders=(load, resolve_database),
                              executor="dask" if args.scheduler else "local", workers=args.workers,
                              scheduler=args.scheduler, progress=progress)
    table = result.table()
    failed = int((table["status"] < 0).sum())
    print(f"wrote {store}: {len(table)} trials" + (f", {failed} failed (see their message column)" if failed else ""))
    if args.report:
        files = write_report(store, args.report)
        print(f"wrote {len(files)} report files to {args.report}")
    return 0


def _cmd_report(args) -> int:
    from boatland.campaign.report import write_report

    if not 0.0 < args.target < 1.0:
        raise BoatlandInputError(f"--target must lie in (0, 1), got {args.target}")
    files = write_report(args.store, args.output, incident=args.incident, target=args.target)
    for f in files:
        print(f"wrote {f}")
    return 0


def _cmd_scenario_check(args) -> int:
    from boatland.scenario_check import check_file

    report = check_file(args.file)
    print(report.text)
    return report.exit_status


def _cmd_list(args) -> int:
    from boatland.hydro.builtin import BUILTIN, builtin_path

    for name, text in BUILTIN.items():
        print(f"{name:8s} {text}  [{builtin_path(name)}]")
    return 0


# ------------------------------------------------------------------------- frequency domain (issue 8)
def _freq_load(path):
    """Scenario, database and their landing for the frequency-domain commands (warnings printed)."""
    import warnings

    from boatland.scenario_check import default_scenario_path, load_checked

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scenario, db, _ = load_checked(path or default_scenario_path())
    for w in caught:
        print(f"warning: {w.message}", file=sys.stderr)
    return scenario, db


def _freq_sea(scenario):
    """(spectral shape, relative direction [deg] or None) of the scenario's sea."""
    waves = scenario.sea.waves if scenario.sea is not None else None
    parts = getattr(waves, "parts", None)
    if not parts:
        direction = getattr(waves, "direction_deg", None)
        return None, None if direction is None else (direction - scenario.vessel.heading_deg) % 360
    return parts[0], (parts[0].direction_deg - scenario.vessel.heading_deg) % 360


def _freq_check(args) -> None:
    """Refuse bad screening options before loading anything."""
    from boatland.freqdomain import accept_probability

    accept_probability(args.accept)
    for name, value in (("--mu", args.mu), ("--thrust", args.thrust), ("--access", args.access),
                        ("--roll-limit", args.roll_limit)):
        if value is not None and not value > 0:
            raise BoatlandInputError(f"{name} {value:g}: must be > 0")


def _freq_directions(scenario, db, beta, key: str) -> None:
    """Refuse relative directions the database does not cover, naming the option (``key``) that gave them."""
    import numpy as np

    from boatland.model.wave_directions import direction_problem

    problem = direction_problem(db, np.atleast_1d(beta), name=repr(scenario.vessel.database or db.name))
    if problem:
        raise BoatlandInputError(f"{key}: {problem}")


def _freq_setup(args, scenario, db):
    from boatland.freqdomain import LandingSetup

    return LandingSetup.from_scenario(scenario, db, roll_limit_deg=args.roll_limit)


def _cmd_rao(args) -> int:
    import numpy as np

    from boatland.freqdomain import LandingSetup, free_rao, hinged_rao, point_map

    scenario, db = _freq_load(args.scenario)
    setup = LandingSetup.from_scenario(scenario, db)
    beta = args.direction
    key = "--direction"
    if beta is None:
        beta = _freq_sea(scenario)[1]
        key = f"{scenario.source}: sea: relative direction"
        if beta is None:
            beta, key = 180.0, "relative direction (default 180°: no --direction and no sea)"
    _freq_directions(scenario, db, beta, key)
    T = np.asarray(args.periods, dtype=float)
    if np.any(T <= 0):
        raise BoatlandInputError(f"--periods: all must be > 0 s, got {args.periods}")
    if np.any(2 * np.pi / T > db.omega[-1]):
        raise BoatlandInputError(f"--periods: {T.min():g} s is shorter than the database {db.name!r} covers "
                                 f"(ω ≤ {db.omega[-1]:g} rad/s: T ≥ {2 * np.pi / db.omega[-1]:.3g} s)")

    def solve(w):
        x = free_rao(db, w, beta, additional_damping=setup.additional_damping)[:, 0]
        h = hinged_rao(db, w, setup.points, beta_deg=beta, normal=setup.normals, stiffness=setup.stiffness,
                       damping=setup.damping, thrust=setup.thrust, thrust_position=setup.thrust_position,
                       additional_damping=setup.additional_damping)
        bow = x @ point_map(setup.points[0]).T
        return x, bow, h.x[:, 0], h.contact_components()[:, 0].sum(axis=1)

    w = 2 * np.pi / T
    x, bow, xh, F = solve(w)
    rows = [{"T": float(t), "omega": float(o), "free_heave": abs(x[i, 2]), "free_pitch_deg": np.degrees(abs(x[i, 4])),
             "free_roll_deg": np.degrees(abs(x[i, 3])), "bow_vertical": abs(bow[i, 2]),
             "hinged_pitch_deg": np.degrees(abs(xh[i, 4])), "hinged_roll_deg": np.degrees(abs(xh[i, 3])),
             "normal_kN": abs(F[i, 0]) / 1e3, "vertical_kN": abs(F[i, 1]) / 1e3, "horizontal_kN": abs(F[i, 2]) / 1e3}
            for i, (t, o) in enumerate(zip(T, w))]
    if args.json:
        print(json.dumps({"scenario": scenario.name, "database": db.name, "beta_deg": beta, "rows": rows},
                         indent=2, default=float))
    else:
        print(f"{scenario.name}: {db.name}, relative wave direction {beta:g}° (180 = head seas), per unit wave "
              f"amplitude; hinged at {len(setup.points)} fender point(s), {setup.thrust / 1e3:g} kN thrust")
        print(f"{'T [s]':>6} {'heave':>7} {'pitch':>7} {'roll':>7} {'bow z':>7} | {'pitch':>7} {'roll':>7} | "
              f"{'F_n':>7} {'F_v':>7} {'F_h':>7}")
        print(f"{'':>6} {'free m/m':>7} {'°/m':>7} {'°/m':>7} {'m/m':>7} | {'hinged':>7} {'°/m':>7} | "
              f"{'kN/m':>7} {'kN/m':>7} {'kN/m':>7}")
        for r in rows:
            print(f"{r['T']:6.2f} {r['free_heave']:7.3f} {r['free_pitch_deg']:7.2f} {r['free_roll_deg']:7.2f} "
                  f"{r['bow_vertical']:7.3f} | {r['hinged_pitch_deg']:7.2f} {r['hinged_roll_deg']:7.2f} | "
                  f"{r['normal_kN']:7.1f} {r['vertical_kN']:7.1f} {r['horizontal_kN']:7.1f}")
    if args.output:
        from boatland.freqdomain.figures import plot_raos

        wf = np.linspace(max(2 * np.pi / 25.0, db.omega[0]), db.omega[-1], 300)  # T ≤ 25 s
        plot_raos(wf, *solve(wf), args.output,
                  title=f"{scenario.name}: {db.name}, β = {beta:g}° (relative), per unit wave amplitude")
        if not args.json:
            print(f"wrote {args.output}")
    if args.compare_open_sea:
        _compare_open_sea(scenario, db, setup, args)
    return 0


def _compare_open_sea(scenario, db, setup, args) -> None:
    import numpy as np

    from boatland.freqdomain.figures import plot_pile_comparison
    from boatland.freqdomain.pile import COMPARE_HEADINGS, rao_with_pile

    if scenario.landing is None:
        raise BoatlandInputError(f"{scenario.source}: landing: --compare-open-sea needs the monopile of a [landing]")
    x0, y0, psi = scenario.start_pose()
    px, py = scenario.landing.monopile_position
    wf = np.linspace(max(2 * np.pi / 25.0, db.omega[0]), db.omega[-1], 200)
    open_sea, near = rao_with_pile(db, wf, (x0 - px, y0 - py), float(np.degrees(psi)),
                                   scenario.landing.monopile_diameter / 2,
                                   additional_damping=setup.additional_damping)
    plot_pile_comparison(wf, open_sea, near, COMPARE_HEADINGS, args.compare_open_sea,
                         title=f"{scenario.name}: {db.name} beside a {scenario.landing.monopile_diameter:g} m "
                               "monopile vs the open sea (free vessel, per unit wave amplitude)")
    if not args.json:
        print(f"wrote {args.compare_open_sea}")


def _cmd_screen(args) -> int:
    import numpy as np

    from boatland.freqdomain import screening_grid

    _freq_check(args)
    scenario, db = _freq_load(args.scenario)
    setup = _freq_setup(args, scenario, db)
    lo, hi, n = args.tp
    if not (0 < lo <= hi and n >= 1 and n == int(n)):
        raise BoatlandInputError(f"--tp {lo:g} {hi:g} {n:g}: need 0 < MIN ≤ MAX and a whole N ≥ 1")
    if args.directions < 1:
        raise BoatlandInputError(f"--directions {args.directions}: need N ≥ 1")
    Tp = np.linspace(lo, hi, int(n))
    beta = np.arange(args.directions) * 360.0 / args.directions
    _freq_directions(scenario, db, beta, f"--directions {args.directions} (every {360.0 / args.directions:g}°)")
    sea, _ = _freq_sea(scenario)
    depth = scenario.sea.water_depth if scenario.sea is not None else None
    table = screening_grid(db, setup, Tp, beta, accept=args.accept, statistics=args.statistics, method=args.method,
                           sea=sea, water_depth=depth, access_duration=args.access, mu=args.mu, thrust=args.thrust)
    mu = setup.mu if args.mu is None else args.mu
    thrust = setup.thrust if args.thrust is None else args.thrust
    if args.json:
        print(json.dumps({"scenario": scenario.name, "database": db.name, "accept": table.accept,
                          "statistics": table.statistics, "method": table.method, "mu": mu, "thrust": thrust,
                          "roll_limit_deg": setup.roll_limit_deg, "Tp": table.Tp.tolist(),
                          "beta_deg": table.beta_deg.tolist(),
                          "Hs_limit": [[None if not np.isfinite(h) else float(h) for h in row] for row in table.Hs],
                          "governing": table.governing.tolist()}, indent=2))
    else:
        print(f"{scenario.name}: limiting Hs [m] for P_acc = {table.accept:g} per {args.access:g} s access "
              f"({table.statistics}, {table.method} hinge; μ = {mu:g}, F_b = {thrust / 1e3:g} kN, "
              f"θ_max = {setup.roll_limit_deg:g}°); rows Tp, columns relative direction (180 = head seas)")
        print(table.text())
        modes, counts = np.unique(table.governing[np.isfinite(table.Hs)], return_counts=True)
        print("governing: " + ", ".join(f"{m} {c}" for m, c in zip(modes, counts)))
        parts = getattr(scenario.sea.waves, "parts", None) if scenario.sea is not None else None
        if parts:
            from boatland.freqdomain import sea_response

            r = sea_response(db, setup.replace(mu=mu, thrust=thrust), parts, water_depth=depth,
                             statistics=table.statistics, method=table.method, access_duration=args.access)
            print(f"the scenario's own sea ({', '.join(f'Hs {p.Hs:g} m Tp {p.Tp:g} s' for p in parts)}): incident "
                  f"probability {r.p_access:.3g} per access ({r.p_cycle:.3g} per {r.cycle_period:g} s cycle); "
                  "σ of the margins " + ", ".join(f"{m} {s / 1e3:.3g} kN" for m, s in zip(r.names[:-1], r.sigma))
                  + "; capacities " + ", ".join(f"{a / 1e3:.3g} kN" for a in r.capacity[:-1]))
        if table.captured.min() < 0.99:
            print(f"note: the database's band holds {100 * table.captured.min():.1f} % of the wave variance at "
                  f"Tp = {table.Tp[np.argmin(table.captured)]:g} s (the rest is left out)")
    if args.output:
        from boatland.freqdomain.figures import plot_limits

        plot_limits(table, args.output)
        if not args.json:
            print(f"wrote {args.output}")
    return 0


def _cmd_operability(args) -> int:
    import warnings

    from boatland.errors import BoatlandWarning
    from boatland.freqdomain import availability, read_scatter

    _freq_check(args)
    scenario, db = _freq_load(args.scenario)
    setup = _freq_setup(args, scenario, db)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BoatlandWarning)
        scatter = read_scatter(args.scatter)
    for w in caught:
        print(f"warning: {w.message}", file=sys.stderr)
    _freq_directions(scenario, db, (scatter.direction_deg - setup.heading_deg) % 360.0,
                     f"{args.scatter}: direction (relative to the vessel's heading {setup.heading_deg:g}°)")
    sea, _ = _freq_sea(scenario)
    depth = scenario.sea.water_depth if scenario.sea is not None else None
    a = availability(db, setup, scatter, accept=args.accept, statistics=args.statistics, method=args.method,
                     sea=sea, water_depth=depth, access_duration=args.access, mu=args.mu, thrust=args.thrust)
    if args.json:
        print(json.dumps({"scenario": scenario.name, "scatter": str(args.scatter), "availability": a.availability,
                          "downtime": a.downtime, "accept": a.accept, "statistics": a.statistics,
                          "method": a.method, "mu": a.mu, "thrust": a.thrust, "sea_states": int(a.workable.size),
                          "workable_sea_states": int(a.workable.sum())}, indent=2))
    else:
        print(f"{scenario.name} over {args.scatter} ({a.workable.size} sea states): availability "
              f"{100 * a.availability:.1f} % (downtime {100 * a.downtime:.1f} %)")
        print(f"  μ = {a.mu:g}, F_b = {a.thrust / 1e3:g} kN (μ·F_b = {a.mu * a.thrust / 1e3:g} kN), "
              f"P_acc = {a.accept:g} per {args.access:g} s access, {a.statistics}, {a.method} hinge")
    return 0
